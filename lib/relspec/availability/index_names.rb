# frozen_string_literal: true

require_relative "../apt/packages_scanner"

module Relspec
  module Availability
    # The binary package names one apt index makes installable: real
    # packages (Architecture: all ones included, as the binary-<arch>
    # indices list them) and virtual names with the packages that provide
    # them. Only names matter here, so only two fields are read. Real names
    # are kept sorted and searched by bisection: loading a cached index is
    # then one split, not the building of a 60,000-entry Hash.
    class IndexNames
      FIELDS = %w[Package Provides].freeze
      SEPARATOR = "--- provided ---"

      # +real+: sorted unique names; +virtual+: {name => [providers]}.
      def initialize(real, virtual)
        @real = real.freeze
        @virtual = virtual.freeze
        freeze
      end

      # From the text of a Packages index.
      def self.parse(text)
        real = []
        virtual = {}
        Apt::PackagesScanner.new(text).each(FIELDS) do |stanza|
          name = stanza["Package"]
          next unless name

          real << name
          stanza["Provides"]&.split(",")&.each do |relation|
            provided = relation.strip[/\A[^\s(:]+/]
            (virtual[provided] ||= []) << name if provided
          end
        end
        new(real.sort.uniq, virtual)
      end

      # The cached form written by #dump: sorted names, a separator line,
      # then "virtual<TAB>providers" lines.
      def self.load(text)
        real, provided = text.split("\n#{SEPARATOR}\n", 2)
        virtual = provided.to_s.split("\n").to_h do |line|
          name, providers = line.split("\t", 2)
          [name, providers.to_s.split]
        end
        new(real.split("\n"), virtual)
      end

      def dump
        "#{@real.join("\n")}\n#{SEPARATOR}\n#{@virtual.map { |name, by| "#{name}\t#{by.join(' ')}" }.join("\n")}\n"
      end

      # :real, [providers] or nil.
      def lookup(name)
        return :real if @real.bsearch { |candidate| name <=> candidate }

        @virtual[name]
      end

      # Every name a relation can be satisfied by (for hints).
      def names
        @real + @virtual.keys
      end

      def inspect
        "#<#{self.class.name} #{@real.size} packages, #{@virtual.size} virtual names>"
      end
    end
  end
end
