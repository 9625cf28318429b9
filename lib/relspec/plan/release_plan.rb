# frozen_string_literal: true

module Relspec
  module Plan
    # The decisions for every target of a release, with what was read to make
    # them; immutable. Lock (the file) and the renderers read from it.
    class ReleasePlan
      attr_reader :release, :targets, :unavailable, :packages, :release_digests, :warnings, :notes

      # +targets+: Target => {package name => Decision}; +unavailable+:
      # Target => {package name => Cause} for the selected packages that
      # cannot exist there; +packages+: package name => source record;
      # +release_digests+: [ancestor, codename] => SHA256 of what the ancestor provides there (Inventory);
      def initialize(release:, targets:, packages:, release_digests:, warnings:, notes:, unavailable: {})
        @release = release
        @targets = targets.freeze
        @unavailable = targets.keys.to_h { |target| [target, unavailable.fetch(target, {}).freeze] }.freeze
        @packages = packages.freeze
        @release_digests = release_digests.freeze
        @warnings = warnings.freeze
        @notes = notes.freeze
        freeze
      end

      def decision(target, package)
        targets.fetch(target).fetch(package)
      end

      def counts(target)
        decisions = targets.fetch(target).values
        { inherit: decisions.count(&:inherit?), build: decisions.count(&:build?),
          published: decisions.count(&:published?), system: decisions.count(&:system?),
          unavailable: unavailable.fetch(target).size }
      end

      # Returns the same plan with other decisions (Settlement gives
      # versions) and +warnings+ added (about those versions).
      def with_targets(targets, warnings: [])
        ReleasePlan.new(release: release, targets: targets, packages: packages, release_digests: release_digests,
                        warnings: self.warnings + warnings, notes: notes, unavailable: unavailable)
      end

      def builds(target)
        targets.fetch(target).values.select(&:build?)
      end
    end
  end
end
