# frozen_string_literal: true

require_relative "../apt/version"
require_relative "gem_version"

module Relspec
  module Debian
    # The version of a package built in a release (docs/compile.md, Names and versions): upstream
    # `<manifest version or 0>.<YYYYMMDD>.<HHMMSS>` of the UTC commit time (a
    # gem's own version for gems), then `-<revision>~<codename>` so that one
    # repository can hold one build per distribution.
    #
    # This is the only place that formats or reads such versions. A value is
    # immutable and compares as dpkg does (through Apt::Version), so "is this
    # version in the repository?" never depends on how a string was spelled.
    class PackageVersion
      include Comparable

      CODENAME = /\A[a-z][a-z0-9-]*\z/
      FULL = /\A(?<upstream>[0-9][A-Za-z0-9.+~]*)-(?<revision>[1-9][0-9]*)~(?<codename>[a-z][a-z0-9-]*)\z/

      attr_reader :upstream, :revision, :codename

      # The version relspec gives a build, or nil when +text+ is not one
      # (an ancestor built by another tool may use any Debian version).
      def self.parse(text)
        match = FULL.match(text.to_s)
        match && new(match[:upstream], Integer(match[:revision], 10), match[:codename])
      end

      def initialize(upstream, revision, codename)
        raise ArgumentError, "invalid upstream version #{upstream.inspect}" unless upstream.to_s.match?(/\A[0-9][A-Za-z0-9.+~]*\z/)
        raise ArgumentError, "invalid revision #{revision.inspect}" unless revision.is_a?(Integer) && revision.positive?
        raise ArgumentError, "invalid codename #{codename.inspect}" unless codename.to_s.match?(CODENAME)

        @upstream = upstream.dup.freeze
        @revision = revision
        @codename = codename.dup.freeze
        @text = "#{upstream}-#{revision}~#{codename}".freeze
        freeze
      end

      def to_s
        @text
      end

      def to_apt
        Apt::Version.parse(@text)
      end

      def <=>(other)
        to_apt <=> (other.is_a?(PackageVersion) ? other.to_apt : Apt::Version.parse(other.to_s))
      end

      def eql?(other)
        other.is_a?(PackageVersion) && to_s == other.to_s
      end

      def hash
        @text.hash
      end

      # The same upstream version with another revision.
      def with_revision(revision)
        PackageVersion.new(upstream, revision, codename)
      end

      # Does an index's Version field (a string) name exactly this version?
      # dpkg's equality, not string equality ("1.0" is "1.00").
      def same_as?(text)
        return false if text.nil?

        to_apt == Apt::Version.parse(text.to_s)
      rescue ArgumentError
        false
      end

      class << self
        # +commit_time+: "YYYY-MM-DDTHH:MM:SSZ". Returns nil when it is unknown.
        def upstream(manifest_version, commit_time)
          return nil unless commit_time

          date, time = commit_time.delete_suffix("Z").split("T")
          "#{base(manifest_version)}.#{date.delete('-')}.#{time.delete(':')}"
        end

        # The upstream version of a catalog package: the gem version for gems,
        # else made of the manifest version and the commit time.
        def of_package(package)
          package.build_type == "gem" ? GemVersion.to_debian(package.version) : upstream(package.version, package.commit_time)
        end

        # The upstream part of a version relspec made (nil for anything else).
        def upstream_of(text)
          parse(text)&.upstream
        end

        # A manifest version that Debian accepts as the start of an upstream
        # version: digits first, only . + ~ and alphanumerics.
        def base(manifest_version)
          text = manifest_version.to_s.strip.gsub(/[^A-Za-z0-9.+~]/, ".").squeeze(".").delete_suffix(".")
          text.match?(/\A[0-9]/) ? text : "0"
        end
      end
    end
  end
end
