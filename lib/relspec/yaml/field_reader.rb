# frozen_string_literal: true

require_relative "located_document"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Yaml
    # The checks a strict reader of a file relspec writes makes on each
    # field of a LocatedDocument, every failure an InvalidInput at the
    # field's line (+rule+ and +hint+ name the file kind and what to do).
    # Shared by the readers of build-results.yml and plan.yml; a path is
    # the list of keys and indices leading to a value.
    class FieldReader
      attr_reader :document

      def initialize(document, rule:, what:, hint:)
        @document = document
        @rule = rule
        @what = what
        @hint = hint
        return if document.ok?

        raise InvalidInput, document.diagnostics.select(&:error?).map { |d| diagnostic(d.message, d.location) }
      end

      # The document's root, which must be a mapping.
      def root
        data = @document.data
        fail_at([], "the file is empty or not a mapping") unless data.is_a?(Hash)
        data
      end

      def text(hash, path)
        value = hash[path.last]
        fail_at(path, "#{describe(path)} is missing") if value.nil?
        fail_at(path, "#{describe(path)} must be text") unless value.is_a?(String) || value.is_a?(Numeric)

        value.to_s
      end

      def optional_text(hash, path)
        hash[path.last].nil? ? nil : text(hash, path)
      end

      def mapping(hash, path)
        value = hash[path.last]
        return {} if value.nil?
        fail_at(path, "#{describe(path)} must be a mapping") unless value.is_a?(Hash)

        value
      end

      def list(hash, path, of:)
        value = hash[path.last]
        return [] if value.nil?
        fail_at(path, "#{describe(path)} must be a list of #{of}") unless value.is_a?(Array)

        value
      end

      # A name from the file that becomes a path: no absolute path, no "..",
      # no empty part.
      def plain_path(hash, path)
        name = text(hash, path)
        inside = !name.start_with?("/") && name.split("/").none? { |part| part.empty? || part == "." || part == ".." }
        fail_at(path, "#{describe(path)} #{name.inspect} is not a plain path inside the target folder") unless inside
        name
      end

      def expect(hash, path, wanted)
        value = text(hash, path)
        fail_at(path, "#{describe(path)} is #{value.inspect}, expected #{wanted.inspect}") unless value == wanted
      end

      def known_keys(hash, path, keys)
        unknown = hash.keys - keys
        fail_at(path + [unknown.first], "unknown key #{unknown.first.inspect} in #{describe(path)}") unless unknown.empty?
      end

      def describe(path)
        path.empty? ? "the file" : path.join(".")
      end

      def fail_at(path, message)
        raise InvalidInput, [diagnostic(message, @document.location(path))]
      end

      private

      def diagnostic(message, location)
        Diagnostic.error(@rule, "cannot read #{@what}: #{message}", location: location, hint: @hint)
      end
    end
  end
end
