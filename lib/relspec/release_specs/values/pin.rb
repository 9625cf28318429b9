# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # One `pins:` entry: a package built from +ref+ ("commit", "tag" or
    # "branch") +value+ rather than its checkout's state.
    Pin = Struct.new(:ref, :value, keyword_init: true) do
      # +entry+: {ref => value} as written (the schema allows one key).
      def self.from(entry)
        ref, value = entry.first
        new(ref: ref, value: value)
      end

      def initialize(**)
        super
        freeze
      end

      # The spec's form, as Catalog::Vcs#pinned takes it.
      def to_h
        { ref => value }
      end
    end
  end
end
