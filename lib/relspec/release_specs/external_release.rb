# frozen_string_literal: true

require_relative "values/repository_entry"
require_relative "values/prefixes"

module Relspec
  module ReleaseSpec
    # A release that has no spec in specs/ but is declared in a spec's
    # `external:` section; it is always a leaf of the hierarchy.
    class ExternalRelease
      attr_reader :name, :declared_in

      protected

      attr_reader :entry

      public

      def initialize(name, entry, declared_in)
        @name = name
        @entry = entry
        @declared_in = declared_in
        freeze
      end

      def path_of(key)
        ["external", name, key]
      end

      def key?(key)
        @entry.key?(key)
      end

      def value(key)
        @entry[key]
      end

      # Its repository, paths relative to the declaring spec's folder.
      def repository
        RepositoryEntry.from(@entry.slice("path", "url", "keyring", "trusted"), base: File.dirname(declared_in.path))
      end

      def prefixes
        Prefixes.from(@entry.method(:[]))
      end

      # Two declarations of one external release mean the same release only
      # when they say the same thing.
      def same_entry?(other)
        other.is_a?(ExternalRelease) && other.entry == @entry
      end

      def location
        declared_in.key_location(["external", name])
      end
    end
  end
end
