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

      def full(upstream, revision, codename)
        "#{upstream}-#{revision}~#{codename}"
      end

      # The upstream part of a full version we made (nil for anything else).
      def upstream_of(version)
        version[/\A(.*)-\d+~[a-z0-9-]+\z/, 1]
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
