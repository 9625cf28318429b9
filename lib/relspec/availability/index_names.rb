# frozen_string_literal: true

require_relative "../apt/packages_scanner"

module Relspec
  module Availability
    # The binary package names that apt indices of one target make
    # installable: real packages (Architecture: all ones included, as the
    # binary-<arch> indices list them) and virtual names with the packages
    # that provide them. Only names matter here, so only two fields are read.
    class IndexNames
      FIELDS = %w[Package Provides].freeze

      # +real+: {name => true}; +virtual+: {name => [providers]}.
      def initialize(real, virtual)
        @real = real.freeze
        @virtual = virtual.freeze
        freeze
      end

      # From the text of a Packages index.
      def self.parse(text)
        real = {}
        virtual = {}
        Apt::PackagesScanner.new(text).each(FIELDS) do |stanza|
          name = stanza["Package"]
          next unless name

          real[name] = true
          stanza["Provides"]&.split(",")&.each do |relation|
            provided = relation.strip[/\A[^\s(:]+/]
            (virtual[provided] ||= []) << name if provided
          end
        end
        new(real, virtual)
      end

      # The cached form written by #dump: "name" or "virtual<TAB>providers".
      def self.load(text)
        real = {}
        virtual = {}
        text.each_line(chomp: true) do |line|
          name, providers = line.split("\t", 2)
          providers ? virtual[name] = providers.split(" ") : real[name] = true
        end
        new(real, virtual)
      end

      def self.merge(all)
        return all.first if all.size == 1

        virtual = {}
        all.each { |names| names.virtual.each { |name, by| (virtual[name] ||= []).concat(by) } }
        new(all.map(&:real).reduce({}, :merge), virtual.transform_values(&:uniq))
      end

      def dump
        (@real.keys.map { |name| "#{name}\n" } + @virtual.map { |name, by| "#{name}\t#{by.join(' ')}\n" }).join
      end

      # :real, [providers] or nil.
      def lookup(name)
        return :real if @real.key?(name)

        @virtual[name]
      end

      # Every name a relation can be satisfied by (for hints).
      def names
        @real.keys + @virtual.keys
      end

      # {name => true} and {name => [providers]}, for merging.
      attr_reader :real, :virtual

      def inspect
        "#<#{self.class.name} #{@real.size} packages, #{@virtual.size} virtual names>"
      end
    end
  end
end
