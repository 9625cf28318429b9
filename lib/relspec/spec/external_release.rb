# frozen_string_literal: true

module Relspec
  module Spec
    # A release that has no spec in specs/ but is declared in a spec's
    # `external:` section; it is always a leaf of the hierarchy.
    class ExternalRelease
      attr_reader :name, :declared_in

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

      def location
        declared_in.key_location(["external", name])
      end
    end
  end
end
