# frozen_string_literal: true

module Relspec
  module Plan
    # Every build a release has made, per target and package and upstream
    # version: the last revision given and the digest of the debian/ it was
    # made from. Kept in the lock whatever the current selection, so that a
    # package that leaves the release and comes back goes on from its last
    # revision, and an upstream version built again (a pin moved back) never
    # reuses a revision for other bytes. Immutable.
    class History
      # +kept+: why the early cutoff kept this revision for +debian_digest+
      # (the debian/ naming its dependencies' new versions), nil for a
      # revision built from it (docs/abi.md).
      Build = Struct.new(:revision, :debian_digest, :kept, keyword_init: true)

      EMPTY = {}.freeze

      # +builds+: "codename/arch" => package => upstream => Build
      def initialize(builds = {})
        @builds = builds.transform_values { |packages| packages.transform_values(&:freeze).freeze }.freeze
        freeze
      end

      def self.empty
        new({})
      end

      # The Build recorded for this upstream version, or nil.
      def build(target, package, upstream)
        @builds.dig(target.to_s, package, upstream)
      end

      # Every upstream version recorded for +package+ on +target+.
      def upstreams(target, package)
        @builds.dig(target.to_s, package)&.keys || []
      end

      # A history that also records +version+ (a PackageVersion) of
      # +package+ made from +debian_digest+.
      def with(target, package, version, debian_digest)
        with_all([[target, package, version, debian_digest]])
      end

      # A history that also records every [target, package, version,
      # debian_digest, kept (optional)] of +builds+, copied once (a copy per
      # build made recording a plan's builds grow with the square of their
      # number).
      def with_all(builds)
        added = builds.each_with_object({}) do |(target, package, version, debian_digest, kept), out|
          ((out[target.to_s] ||= {})[package] ||= {})[version.upstream] =
            Build.new(revision: version.revision, debian_digest: debian_digest, kept: kept).freeze
        end
        History.new(@builds.merge(added) do |_, packages, new_packages|
          packages.merge(new_packages) { |_, upstreams, new_upstreams| upstreams.merge(new_upstreams) }
        end)
      end

      def size
        @builds.values.sum { |packages| packages.values.sum(&:size) }
      end

      def empty?
        size.zero?
      end

      # Sorted plain data for the lock.
      def to_h
        @builds.sort.to_h do |target, packages|
          [target, packages.sort.to_h do |package, upstreams|
            [package, upstreams.sort_by { |upstream, _| Apt::Version.parse(upstream) }.to_h do |upstream, build|
              [upstream, { "revision" => build.revision, "debian_digest" => build.debian_digest, "kept" => build.kept }.compact]
            end]
          end]
        end
      end
    end
  end
end
