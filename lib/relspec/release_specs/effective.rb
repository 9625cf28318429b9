# frozen_string_literal: true

require_relative "distribution"
require_relative "defaults"
require_relative "values/repository_entry"
require_relative "values/early_cutoff"
require_relative "values/blacklist_entry"
require_relative "values/leave_out"
require_relative "values/pin"
require_relative "values/prefixes"
require_relative "../frozen"

module Relspec
  module ReleaseSpec
    # A release as relspec uses it: its own values plus everything inherited,
    # each value with the Origin it came from. Immutable, all the way down:
    # every reader of the spec shares its values.
    class EffectiveSpec
      # Key order of `relspec show`: identity, lineage, content, packaging.
      KEYS = %w[
        release description parent ancestors workspace select blacklist leave_out pins gems gem_source targets
        repository install_prefix separate_prefixes package_prefix maintainer external distributions early_cutoff
      ].freeze

      attr_reader :values, :origins

      # +values+: key => value; +origins+: key => Origin, and for pins
      # "pins" => { package => Origin } because pins merge entry by entry.
      def initialize(values, origins)
        @values = Frozen.deep(values)
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

      # The typed values below are what the pipeline reads; the raw mapping
      # ([] and to_h) is for show, diff and the rules.

      # The release's own RepositoryEntry (paths relative to the spec that
      # wrote it), or nil.
      def repository
        origin = origins["repository"]
        origin && RepositoryEntry.from(values["repository"], base: File.dirname(origin.file.path))
      end

      # The release's EarlyCutoff setting (on when the spec says nothing).
      def early_cutoff
        EarlyCutoff.from(values["early_cutoff"])
      end

      # BlacklistEntry values in spec order.
      def blacklist
        (values["blacklist"] || []).each_with_index.map { |entry, index| BlacklistEntry.from(entry, index) }
      end

      # The release's own LeaveOut (never inherited).
      def leave_out
        LeaveOut.from(values["leave_out"] || [])
      end

      # The codenames each `leave_out` entry names, as written and in entry
      # order (one whose match does not parse too, which LeaveOut skips):
      # what HierarchyRules checks against the targets and locates.
      def leave_out_codenames
        (values["leave_out"] || []).map { |entry| entry["targets"] || [] }
      end

      # package name => Pin, merged over the ancestors.
      def pins
        (values["pins"] || {}).transform_values { |entry| Pin.from(entry) }
      end

      def prefixes
        Prefixes.from(values.method(:[]))
      end

      def parents
        Array(values["parent"])
      end

      # The workspace (or catalog snapshot) as written, relative to the spec's folder.
      def workspace
        values["workspace"]
      end

      # `select` as written, nil for the workspace's layout.
      def select
        values["select"]
      end

      def maintainer
        values["maintainer"]
      end

      # gem name => version of `gems:`.
      def gems
        values["gems"] || {}
      end

      def gem_source
        values.fetch("gem_source", DEFAULTS["gem_source"])
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
