# frozen_string_literal: true

require_relative "../package_pattern"

module Relspec
  module ReleaseSpec
    # The spec's `leave_out`: packages a release (or some of its target
    # distributions) does without, each with the reason. The catalog's
    # selection leaves the matches out with what requires them, and the
    # plan says why.
    class LeaveOut
      # +pattern+: PackagePattern; +codenames+: nil for every target;
      # +index+: the entry's place in the list, for locations.
      Entry = Struct.new(:pattern, :reason, :codenames, :index, keyword_init: true) do
        def applies_to?(codename)
          codenames.nil? || codenames.include?(codename)
        end
      end

      attr_reader :entries

      # +list+: the `leave_out` entries as written. Entries whose match cannot
      # be parsed are the file rules' errors; they are skipped here.
      def self.from(list)
        entries = list.each_with_index.filter_map do |entry, index|
          pattern = PackagePattern.parse(entry["match"])
          next if pattern.is_a?(PackagePattern::Invalid)

          Entry.new(pattern: pattern, reason: entry["reason"], codenames: entry["targets"]&.uniq&.freeze, index: index).freeze
        end
        new(entries)
      end

      def initialize(entries)
        @entries = entries.freeze
        freeze
      end

      def empty?
        entries.empty?
      end

      # The first entry leaving +name+ out on +codename+, or nil.
      def match(name, codename)
        entries.find { |entry| entry.applies_to?(codename) && entry.pattern.match?(name) }
      end
    end
  end
end
