# frozen_string_literal: true

module Relspec
  module Plan
    # The decisions for every target of a release, with what was read to make
    # them; immutable. Lock (the file) and the renderers read from it.
    class ReleasePlan
      attr_reader :release, :targets, :packages, :release_digests, :warnings, :notes

      # +targets+: Target => {package name => Decision}; +packages+: package
      # name => source record; +release_digests+: [ancestor, codename] =>
      # SHA256 of the Release file read.
      def initialize(release:, targets:, packages:, release_digests:, warnings:, notes:)
        @release = release
        @targets = targets.freeze
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
          published: decisions.count(&:published?) }
      end

      def builds(target)
        targets.fetch(target).values.select(&:build?)
      end
    end
  end
end
