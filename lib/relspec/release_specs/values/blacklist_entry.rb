# frozen_string_literal: true

require_relative "../package_pattern"

module Relspec
  module ReleaseSpec
    # One `blacklist:` entry: which packages it rebuilds (+pattern+, a
    # PackagePattern) and why (+reason+, or nil); +index+ is its position in
    # the spec, for diagnostics.
    BlacklistEntry = Struct.new(:pattern, :reason, :index, keyword_init: true) do
      # +entry+: {"match" => …, "reason" => …} as inheritance normalised it.
      def self.from(entry, index)
        new(pattern: PackagePattern.parse(entry["match"]), reason: entry["reason"], index: index)
      end

      def initialize(**)
        super
        freeze
      end

      def match?(name)
        pattern.match?(name)
      end
    end
  end
end
