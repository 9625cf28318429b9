# frozen_string_literal: true

require "digest"
require_relative "build_order"
require_relative "debian_inputs"
require_relative "versioning"
require_relative "rising_upstream"
require_relative "cutoff_candidate"
require_relative "../debian/debian_dir"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # Settles the version of every build of a plan, target by target,
    # dependencies first: a package's debian/ names the versions of its
    # dependencies, so their revisions must be known before its own digest
    # is. This runs during planning, so plan, why, compile, osdeps and the
    # builder all read the same versions (docs/design.md, One truth for versions).
    class Settlement
      # What compile needs to emit one build: the DebianDir +input+, the
      # +overlay+ and the +digest+ of debian/ the version was settled from.
      Work = Struct.new(:input, :overlay, :digest, keyword_init: true)

      # +inputs+: DebianInputs; +versioning+: Versioning; +overlays+: the
      # Debian::Overlay of a package on a target (+overlays.call(name,
      # target)+: its codename's and architecture's layers), read from
      # overlays/ by Plan.read.
      # +rising+: RisingUpstream, which keeps a version from going back
      # (nil: versions as the sources make them).
      def initialize(catalog:, inputs:, versioning:, overlays:, rising: nil)
        @catalog = catalog
        @inputs = inputs
        @versioning = versioning
        @overlays = overlays
        @rising = rising
      end

      # [targets with settled decisions, Target => {package => Work},
      # the RisingUpstream::Raised of each build whose version was raised]
      def call(targets)
        work = {}
        @raised = []
        settled = targets.to_h do |target, decisions|
          work[target] = {}
          final = decisions.dup
          BuildOrder.of(@catalog, decisions.keys).each do |name|
            decision = decisions[name]
            next unless decision.build?

            final[name], work[target][name] = settle(target, decision, final)
          end
          [target, final.freeze]
        end
        [settled, work, @raised.dup.freeze]
      end

      private

      # What the source package holds besides debian/ and the overlay: the
      # package set's patches (in debian/patches) and an archive import's
      # checksum (same modification time, other bytes: a new revision).
      # Empty for the others, so their digests stay what they were.
      def source_signature(package)
        parts = package.patches.map { |patch| "#{patch.path}\0#{patch.level}\0#{patch.content}" }
        parts << "archive\0#{package.vcs.sha256}" if package.vcs.sha256
        parts.join("\0")
      end

      def upstream_of(target, decision, package)
        upstream = Debian::PackageVersion.of_package(package)
        return upstream unless @rising

        upstream, raised = @rising.call(target: target, package: package.name, deb_name: decision.deb_name, upstream: upstream,
                                        import: !package.vcs.sha256.nil?)
        @raised << raised if raised
        upstream
      end

      def settle(target, decision, decisions)
        package = @catalog.package(decision.package)
        upstream = upstream_of(target, decision, package)
        input = @inputs.for(target, decision, upstream, decisions)
        overlay = @overlays.call(package.name, target)
        digest = digest_of(input, overlay, package)
        result = @versioning.settle(target: target, package: package.name, deb_name: decision.deb_name,
                                    upstream: upstream, digest: digest)
        cutoff = result.published ? nil : candidate(target, decision, package, upstream, decisions, overlay)
        final = Decision.new(**decision.each_pair.to_h, kind: result.published ? :published : :build,
                                                        version: result.version, debian_digest: digest,
                                                        depends: @inputs.dependency_names(package, decisions).uniq.sort.freeze,
                                                        cutoff: cutoff, kept: result.kept)
                        .freeze
        [final, Work.new(input: input, overlay: overlay, digest: digest).freeze]
      end

      def digest_of(input, overlay, package)
        Digest::SHA256.hexdigest(Debian::DebianDir.digest(Debian::DebianDir.render(input, version: nil)) +
                                 overlay.signature + source_signature(package))
      end

      # A CutoffCandidate when the build's debian/, with the dependencies
      # rebuilt now at the versions the repository holds, is the one of the
      # published build the history vouches for: only those dependencies'
      # versions moved it. nil otherwise.
      def candidate(target, decision, package, upstream, decisions, overlay)
        kept, recorded = @versioning.previous(target: target, package: package.name, deb_name: decision.deb_name,
                                              upstream: upstream)
        return nil unless kept

        published = @inputs.dependency_names(package, decisions).uniq.filter_map do |name|
          dependency = decisions[name]
          held = dependency.build? && @versioning.published(target, dependency.deb_name)
          held && held.to_s != dependency.version.to_s ? [name, Decision.new(**dependency.each_pair.to_h, version: held).freeze] : nil
        end.to_h
        return nil if published.empty?

        before = @inputs.for(target, decision, upstream, decisions.merge(published))
        return nil unless digest_of(before, overlay, package) == recorded

        CutoffCandidate.new(keeps: kept, because: published.keys.sort.freeze,
                            debian_digest: kept_digest(target, decision, package, upstream, decisions, overlay),
                            against: against(target, @inputs.dependency_names(package, decisions), decisions)).freeze
      end

      # deb_name => the version the repository holds, of each build of the
      # closure of +names+ (through the builds' +depends+, as the plan's
      # build_depends go): what the kept build was made against, so the
      # early cutoff compares new builds with those and not with a build
      # made since and not published (docs/abi.md).
      def against(target, names, decisions)
        held = {}
        seen = {}
        pending = names.dup
        until pending.empty?
          dependency = decisions[pending.pop]
          next unless dependency&.build? && !seen[dependency.package]

          seen[dependency.package] = true
          version = @versioning.published(target, dependency.deb_name)
          held[dependency.deb_name] = version.to_s.freeze if version
          pending.concat(dependency.depends || [])
        end
        held.sort.to_h.freeze
      end

      # The digest of the candidate's debian/ with each dependency that is
      # a candidate itself at the version it keeps (CutoffCandidate).
      def kept_digest(target, decision, package, upstream, decisions, overlay)
        kept = @inputs.dependency_names(package, decisions).uniq.filter_map do |name|
          cutoff = decisions[name]&.cutoff
          cutoff ? [name, Decision.new(**decisions[name].each_pair.to_h, version: cutoff.keeps).freeze] : nil
        end.to_h
        digest_of(@inputs.for(target, decision, upstream, decisions.merge(kept)), overlay, package)
      end
    end
  end
end
