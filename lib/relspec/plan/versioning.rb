# frozen_string_literal: true

require_relative "history"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # The one place that decides the version of a package built here and
    # whether the release's repository already holds it (docs/design.md, One truth for versions).
    #
    # The revision starts at 1 for a new upstream version and goes up when
    # debian/ changes for the same upstream version. The history (from the
    # lock) says which revision was made from which debian/; the repository
    # is the second witness: a revision it holds that the history does not
    # vouch for (a lock lost or discarded, a repository ahead of the lock) is
    # never given again, so a repository never receives two different files
    # under one name.
    class Versioning
      # +kept+: the history's reason when the published version is one the
      # early cutoff kept for this debian/ (docs/abi.md), else nil.
      Settled = Struct.new(:version, :published, :kept, keyword_init: true)

      # +history+: History; +own+: OwnRepository.
      def initialize(history:, own:)
        @history = history
        @own = own
      end

      # Settled version of +package+ (Debian name +deb_name+) on +target+,
      # made from +upstream+ and a debian/ whose digest is +digest+.
      def settle(target:, package:, deb_name:, upstream:, digest:)
        recorded = @history.build(target, package, upstream)
        revision = revision_from(recorded, digest)
        vouched = recorded && recorded.revision == revision && recorded.debian_digest == digest
        held = Debian::PackageVersion.parse(@own.version_of(deb_name, target))
        if held && held.upstream == upstream && held.codename == target.codename && (held.revision > revision || (held.revision == revision && !vouched))
          revision = held.revision + 1
        end
        version = Debian::PackageVersion.new(upstream, revision, target.codename)
        published = vouched && version.same_as?(@own.version_of(deb_name, target))
        Settled.new(version: version, published: published, kept: published ? recorded.kept : nil).freeze
      end

      # The version of +package+ (+deb_name+) the release's repository
      # holds for +upstream+ on +target+ when the history vouches for it
      # (the revision it records), with the digest of the debian/ it was
      # recorded from: [PackageVersion, digest], or nil. The build an early
      # cutoff would keep (docs/abi.md).
      def previous(target:, package:, deb_name:, upstream:)
        recorded = @history.build(target, package, upstream)
        held = published(target, deb_name)
        return nil unless recorded && held && held.upstream == upstream && held.revision == recorded.revision

        [held, recorded.debian_digest]
      end

      # The version of +deb_name+ the release's repository holds on
      # +target+, as a PackageVersion of the target's codename, or nil.
      def published(target, deb_name)
        held = Debian::PackageVersion.parse(@own.version_of(deb_name, target))
        held && held.codename == target.codename ? held : nil
      end

      private

      def revision_from(recorded, digest)
        return 1 unless recorded

        recorded.debian_digest == digest ? recorded.revision : recorded.revision + 1
      end
    end
  end
end
