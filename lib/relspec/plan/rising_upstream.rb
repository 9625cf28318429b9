# frozen_string_literal: true

require_relative "../apt/version"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # An archive import's upstream version is made of the archive's time of
    # modification, which can move back (an older archive served again, a
    # server's clock): 0.20990101.000000 then 0.20210101.000000. apt never
    # takes a lower version for an upgrade, so such a version is raised
    # above the highest one the release gave the package on the target
    # (its history, and the release's repository, the second witness) the
    # way Debian goes back, "<highest>+really<archive's>", and said
    # (Plan.settle's warning). Only archive imports: a git package moved to
    # an older commit is a pin the user chose, and keeps its version.
    class RisingUpstream
      # +upstream+: the version given; +archive+: the one the archive's
      # time makes; +above+: the highest the release gave before.
      Raised = Struct.new(:package, :target, :archive, :above, :upstream, keyword_init: true)

      # +history+: History; +own+: OwnRepository.
      def initialize(history:, own:)
        @history = history
        @own = own
      end

      # [upstream version, Raised or nil] of +package+ (Debian name
      # +deb_name+) on +target+ whose archive's time makes +upstream+.
      def call(target:, package:, deb_name:, upstream:)
        above = highest(target, package, deb_name)
        return [upstream, nil] if above.nil? || Apt::Version.parse(upstream) >= Apt::Version.parse(above)

        # raised for this archive by an earlier plan already: the same version again
        version = above.end_with?("+really#{upstream}") ? above : "#{above}+really#{upstream}"
        [version, Raised.new(package: package, target: target, archive: upstream, upstream: version,
                             above: version.delete_suffix("+really#{upstream}")).freeze]
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
