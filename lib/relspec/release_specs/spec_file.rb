# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "schema_check"
require_relative "file_rules"
require_relative "names"

module Relspec
  module ReleaseSpec
    # One release spec file, read and checked on its own (without its
    # parents): its values, where each one is written, and what is wrong in it.
    class SpecFile
      # Values that are text even when they look like numbers: `rice: 4.10`
      # is version "4.10", not 4.1, and `labels: [20.10]` is "20.10".
      TEXT_PATHS = [
        ["release"], ["parent"], ["parent", :any], ["gems", :any], ["pins", :any, :any],
        ["distributions", :any, "labels", :any]
      ].freeze

      attr_reader :path, :diagnostics

      def self.load(path)
        new(path, Yaml::LocatedDocument.load(path))
      end

      def initialize(path, document)
        @path = path
        @document = document
        @values = document.ok? ? as_text(document.data, []) : nil
        @broken_keys = []
        @diagnostics = document.diagnostics.dup
        check if document.ok?
        @diagnostics.freeze
        freeze
      end

      def ok?
        @diagnostics.none?(&:error?)
      end

      # The release name as written (nil if the file could not be read as a spec).
      def release
        value(["release"]).is_a?(String) ? value(["release"]) : nil
      end

      # The name the file promises by its own name (specs/<release>.yml).
      def file_release
        File.basename(path, ".*")
      end

      def parents
        parent = value(["parent"])
        list = parent.is_a?(Array) ? parent : [parent]
        # Only valid release names: a name becomes a path (specs/<name>.yml)
        # and `../../elsewhere` must never be opened (rules/parents reports it).
        list.select { |name| Names.release?(name) }.uniq
      end

      # All values, with text-looking numbers kept as text (see TEXT_PATHS).
      def data
        @values
      end

      def value(path)
        path.reduce(@values) do |node, part|
          return nil unless (node.is_a?(Hash) && part.is_a?(String)) || (node.is_a?(Array) && part.is_a?(Integer))

          node[part]
        end
      end

      def key?(key)
        @values.is_a?(Hash) && @values.key?(key)
      end

      # The value of a top-level key if it passed the schema; nil otherwise, so
      # one broken field never hides the checks of the others.
      def usable(key)
        @broken_keys.include?(key) ? nil : value([key])
      end

      def usable?(key)
        key?(key) && !@broken_keys.include?(key)
      end

      def location(path)
        @document.location(path)
      end

      def key_location(path)
        @document.key_location(path)
      end

      private

      def check
        result = SchemaCheck.call(self)
        @broken_keys = result.broken_keys
        @diagnostics.concat(result.diagnostics)
        @diagnostics.concat(FileRules.call(self))
      end

      def as_text(node, path)
        case node
        when Hash then node.to_h { |key, value| [key, as_text(value, path + [key])] }
        when Array then node.each_with_index.map { |value, index| as_text(value, path + [index]) }
        when Integer, Float then text_path?(path) ? @document.raw(path) : node
        else node
        end
      end

      def text_path?(path)
        TEXT_PATHS.any? do |pattern|
          pattern.size == path.size &&
            pattern.zip(path).all? { |want, have| want == :any || want == have }
        end
      end
    end
  end
end
