# frozen_string_literal: true

require_relative "effective"
require_relative "origin"
require_relative "defaults"

module Relspec
  module ReleaseSpec
    # Computes a release's effective spec from its hierarchy (docs/spec-reference.md, Inheritance):
    #
    # - own keys never inherited: release, description, parent, workspace,
    #   select, blacklist, leave_out, repository, external, early_cutoff;
    # - INHERITED keys take the value of the first parent (in `parent` order)
    #   whose effective spec has one, else the built-in default;
    # - pins merge: later parents first, earlier parents over them, the
    #   release's own pins over all.
    class Inheritance
      OWN = %w[release description parent workspace select blacklist leave_out repository external early_cutoff].freeze
      INHERITED = %w[targets install_prefix separate_prefixes package_prefix maintainer distributions gems
                     gem_source].freeze
      # Keys an external release may set for its descendants.
      EXTERNAL_KEYS = %w[targets install_prefix separate_prefixes package_prefix].freeze

      # The value was written but is broken: checks that depend on it stay quiet.
      BROKEN = Object.new.freeze

      def self.call(hierarchy)
        new(hierarchy).call
      end

      def initialize(hierarchy)
        @hierarchy = hierarchy
      end

      def call
        root = @hierarchy.root
        values = {}
        origins = {}
        broken = []
        OWN.each do |key|
          found = own(root, key)
          next unless found

          found == BROKEN ? broken << key : (values[key], origins[key] = found)
        end
        values["blacklist"] = values["blacklist"].map { |entry| entry.is_a?(String) ? { "match" => entry } : entry } \
          if values["blacklist"]
        values["ancestors"] = @hierarchy.ancestors.map(&:name)
        INHERITED.each do |key|
          found = inherited(root, key)
          if found == BROKEN
            broken << key
          else
            values[key], origins[key] = found || [DEFAULTS[key], Origin.default]
            values.delete(key) if values[key].nil?
          end
        end
        values["pins"], origins["pins"] = pins(root)
        [EffectiveSpec.new(values, origins), broken.freeze]
      end

      private

      # [value, origin], BROKEN, or nil when the node does not set +key+.
      def own(node, key)
        source = node.source
        if node.external?
          return nil unless EXTERNAL_KEYS.include?(key) && source.key?(key)

          return [source.value(key), Origin.new(source.declared_in, source.path_of(key))]
        end
        return nil unless source.key?(key)
        return BROKEN unless source.usable?(key)

        [source.value([key]), Origin.new(source, [key])]
      end

      def inherited(node, key)
        found = own(node, key)
        return found if found

        node.parents.each do |parent|
          found = inherited(parent, key)
          return found if found
        end
        nil
      end

      def pins(node)
        values = {}
        origins = {}
        node.parents.reverse_each do |parent|
          parent_values, parent_origins = pins(parent)
          values.merge!(parent_values)
          origins.merge!(parent_origins)
        end
        found = node.external? ? nil : own(node, "pins")
        if found.is_a?(Array) && found[0].is_a?(Hash)
          found[0].each do |package, pin|
            values[package] = pin
            origins[package] = Origin.new(node.source, ["pins", package])
          end
        end
        [values.sort.to_h, origins]
      end
    end
  end
end
