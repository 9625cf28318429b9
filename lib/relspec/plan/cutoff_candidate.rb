# frozen_string_literal: true

module Relspec
  module Plan
    # A build the early cutoff may keep (docs/abi.md, "Early cutoff"): its
    # debian/ moved only because dependencies of the release are rebuilt
    # at new versions (+because+: their names, sorted); with their
    # published versions in its place it is the debian/ of the build the
    # release's repository holds (+keeps+: that PackageVersion). Whether
    # it is kept is decided once those dependencies are built: when the
    # interface of each did not change. +debian_digest+: the digest of its
    # debian/ once kept, its dependencies that are candidates themselves at
    # the versions they keep: what the history vouches the kept version
    # for when they are all kept too (publish; docs/abi.md). +against+:
    # Debian source name => the version the repository holds, of each
    # build of its closure the repository holds: the builds the kept one
    # was made against, the only baseline their new builds' interfaces
    # may be compared with (frozen Hash).
    CutoffCandidate = Struct.new(:keeps, :because, :debian_digest, :against, keyword_init: true) do
      def to_s
        "early cutoff candidate: #{keeps} stays if the interface of #{because.join(', ')} does not change"
      end
    end
  end
end
