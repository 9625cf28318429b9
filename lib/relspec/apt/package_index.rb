# frozen_string_literal: true

require_relative "packages_scanner"
require_relative "version"
require_relative "../printable"

module Relspec
  module Apt
    # The binary packages of one Packages index: for each name, its highest
    # version with the fields the planner uses.
    class PackageIndex
      FIELDS = %w[Package Version Depends Provides Source Architecture].freeze

      Entry = Struct.new(:name, :version, :depends, :provides, :source, :architecture)

      # The index is not what it seems: a stanza without Package or Version,
      # or a Version that is not a Debian version (which must never reach a
      # generated debian/control).
      class Invalid < StandardError; end

      attr_reader :entries

      # Raises Deb822::ParseError (with a line number) or Invalid (naming the
      # stanza).
      #
      # The fast scanner reads only the wanted fields; a stanza without
      # Package or Version means the text is not what it seems, and the full
      # parser is run to say where. (Lines the scanner never looks at are not
      # checked: indices are verified against a signed Release file.)
      def self.parse(text)
        entries = {}
        number = 0
        PackagesScanner.new(text).each(FIELDS) do |stanza|
          number += 1
          name = stanza["Package"]
          version = stanza["Version"]
          unless name && version
            Deb822.parse(text)
            raise Invalid, "stanza #{number} has no Package or Version field"
          end
          unless Version.valid?(version)
            raise Invalid, "stanza #{number} (Package: #{Printable.text(name)}) has an invalid Version #{version.strip.inspect}"
          end

          known = entries[name]
          next if known && Version.parse(version) <= Version.parse(known.version)

          source = stanza["Source"]
          source = source ? source[/\A\S+/] : name
          entries[name] = Entry.new(name, version, stanza["Depends"], stanza["Provides"], source,
                                    stanza["Architecture"]).freeze
        end
        new(entries)
      end

      def initialize(entries)
        @entries = entries.freeze
        freeze
      end

      def [](name)
        entries[name]
      end

      def include?(name)
        entries.key?(name)
      end

      def size
        entries.size
      end

      def names
        entries.keys
      end
    end
  end
end
