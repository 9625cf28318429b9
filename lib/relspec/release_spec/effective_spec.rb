# frozen_string_literal: true

require_relative "distribution"

module Relspec
  module ReleaseSpec
    # A release as relspec uses it: its own values plus everything inherited,
    # each value with the Origin it came from. Immutable.
    class EffectiveSpec
      # Key order of `relspec show`: identity, lineage, content, packaging.
      KEYS = %w[
        release description parent ancestors workspace select blacklist leave_out pins gems gem_source targets
        repository install_prefix separate_prefixes package_prefix maintainer external distributions
      ].freeze

      attr_reader :values, :origins

      # +values+: key => value; +origins+: key => Origin, and for pins
      # "pins" => { package => Origin } because pins merge entry by entry.
      def initialize(values, origins)
        @values = values.freeze
        @origins = origins.freeze
        freeze
      end

      def [](key)
        values[key]
      end

      def release
        values["release"]
      end

      def ancestors
        values["ancestors"] || []
      end

      def targets
        values["targets"] || {}
      end

      def distributions
        Distributions.with_overrides(values["distributions"])
      end

      def origin(key)
        origins[key]
      end

      def pin_origin(package)
        origins.fetch("pins", {})[package]
      end

      # Where entry +name+ of mapping +key+ (inherited as a whole) was
      # written, or nil for a built-in default.
      def entry_location(key, name)
        origin = origins[key]
        origin && !origin.default? ? origin.file.location([key, name]) : nil
      end

      # Values in KEYS order, absent keys left out.
      def to_h
        KEYS.each_with_object({}) { |key, out| out[key] = values[key] if values.key?(key) }
      end
    end
  end
end
