# frozen_string_literal: true

module Relspec
  module Debian
    # Version numbers of the packages relspec builds (DESIGN §5):
    # upstream `<manifest version or 0>.<YYYYMMDD>.<HHMMSS>` of the UTC commit
    # time, full `<upstream>-<revision>~<codename>` so that one repository can
    # hold one build per distribution.
    module PackageVersion
      module_function

      # +commit_time+: "YYYY-MM-DDTHH:MM:SSZ". Returns nil when it is unknown.
      def upstream(manifest_version, commit_time)
        return nil unless commit_time

        date, time = commit_time.delete_suffix("Z").split("T")
        "#{base(manifest_version)}.#{date.delete('-')}.#{time.delete(':')}"
      end

      # A gem's version as a Debian upstream version: a prerelease
      # ("1.0.0.pre") must sort before the release, so it gets a tilde
      # ("1.0.0~pre").
      def of_gem(version)
        version.to_s.sub(/\.(?=[A-Za-z])/, "~")
      end

      # The upstream version of a catalog package: the gem version for gems,
      # else made of the manifest version and the commit time.
      def of_package(package)
        package.build_type == "gem" ? of_gem(package.version) : upstream(package.version, package.commit_time)
      end

      def full(upstream, revision, codename)
        "#{upstream}-#{revision}~#{codename}"
      end

      FULL = /\A(.*)-(\d+)~[a-z0-9-]+\z/

      # [upstream, revision] of a full version we made (nil for anything else).
      def split(version)
        upstream, revision = version.to_s.match(FULL)&.captures
        upstream && [upstream, revision.to_i]
      end

      # The upstream part of a full version we made (nil for anything else).
      def upstream_of(version)
        split(version)&.first
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
