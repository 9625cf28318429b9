# frozen_string_literal: true

require_relative "../apt/version"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # A package's upstream version can move back: an archive import's time
    # of modification (an older archive served again, a server's clock:
    # 0.20990101.000000 then 0.20210101.000000), a gem pinned to an older
    # release (grape 3.1.1 then 3.0.1), a git package moved to an older
    # commit. apt never takes a lower version for an upgrade, and reprepro
    # never replaces a package by a lower one (it skips it and exits 0), so
    # such a version is raised above the highest one the release gave the
    # package on the target (its history, and the release's repository, the
    # second witness) the way Debian goes back, "<highest>+really<given>",
    # and said (Plan.settle's warning).
    class RisingUpstream
      # +upstream+: the version used; +given+: the one the source makes
      # (+import+: an archive import's time); +above+: the highest the
      # release gave before.
      Raised = Struct.new(:package, :target, :given, :above, :upstream, :import, keyword_init: true)

      # +history+: History; +own+: OwnRepository.
      def initialize(history:, own:)
        @history = history
        @own = own
      end

      # [upstream version, Raised or nil] of +package+ (Debian name
      # +deb_name+) on +target+ whose source makes +upstream+ (+import+:
      # an archive import's time).
      def call(target:, package:, deb_name:, upstream:, import: false)
        above = highest(target, package, deb_name)
        return [upstream, nil] if above.nil? || Apt::Version.parse(upstream) >= Apt::Version.parse(above)

        # raised for this version by an earlier plan already: the same version again
        version = above.end_with?("+really#{upstream}") ? above : "#{above}+really#{upstream}"
        [version, Raised.new(package: package, target: target, given: upstream, upstream: version,
                             above: version.delete_suffix("+really#{upstream}"), import: import).freeze]
      end

      private

      # The highest upstream version the history records and the repository
      # holds, or nil.
      def highest(target, package, deb_name)
        held = Debian::PackageVersion.parse(@own.version_of(deb_name, target))
        known = @history.upstreams(target, package) + [held&.upstream].compact
        known.max_by { |version| Apt::Version.parse(version) }
      end
    end
  end
end
