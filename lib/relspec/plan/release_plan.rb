# frozen_string_literal: true

module Relspec
  module Plan
    # The decisions for every target of a release, with what was read to make
    # them; immutable. Lock (the file) and the renderers read from it.
    class ReleasePlan
      attr_reader :release, :targets, :unavailable, :packages, :release_digests, :warnings, :notes, :last_builds

      # +targets+: Target => {package name => Decision}; +unavailable+:
      # Target => {package name => Cause} for the selected packages that
      # cannot exist there; +packages+: package name => source record;
      # +release_digests+: [ancestor, codename] => SHA256 of what the ancestor provides there (Inventory);
      # +last_builds+: Target => {package name => {"version", "debian_digest"}}
      # of packages not built now that an earlier lock recorded as built, so
      # their revisions go on where they stopped if they are built again.
      def initialize(release:, targets:, packages:, release_digests:, warnings:, notes:, unavailable: {}, last_builds: {})
        @release = release
        @targets = targets.freeze
        @unavailable = targets.keys.to_h { |target| [target, unavailable.fetch(target, {}).freeze] }.freeze
        @last_builds = last_builds.freeze
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

      # Returns the same plan with other decisions (compile settles versions).
      def with_targets(targets, last_builds: self.last_builds)
        ReleasePlan.new(release: release, targets: targets, packages: packages, release_digests: release_digests,
                        warnings: warnings, notes: notes, unavailable: unavailable, last_builds: last_builds)
      end

      def builds(target)
        targets.fetch(target).values.select(&:build?)
      end
    end
  end
end
