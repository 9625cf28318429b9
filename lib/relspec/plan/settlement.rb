# frozen_string_literal: true

require "digest"
require_relative "build_order"
require_relative "debian_inputs"
require_relative "versioning"
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
      def initialize(catalog:, inputs:, versioning:, overlays:)
        @catalog = catalog
        @inputs = inputs
        @versioning = versioning
        @overlays = overlays
      end

      # [targets with settled decisions, Target => {package => Work}]
      def call(targets)
        work = {}
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
        [settled, work]
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

      def settle(target, decision, decisions)
        package = @catalog.package(decision.package)
        upstream = Debian::PackageVersion.of_package(package)
        input = @inputs.for(target, decision, upstream, decisions)
        overlay = @overlays.call(package.name, target)
        digest = Digest::SHA256.hexdigest(Debian::DebianDir.digest(Debian::DebianDir.render(input, version: nil)) +
                                          overlay.signature + source_signature(package))
        result = @versioning.settle(target: target, package: package.name, deb_name: decision.deb_name,
                                    upstream: upstream, digest: digest)
        final = Decision.new(**decision.each_pair.to_h, kind: result.published ? :published : :build,
                                                        version: result.version, debian_digest: digest,
                                                        depends: @inputs.dependency_names(package, decisions).uniq.sort.freeze)
                        .freeze
        [final, Work.new(input: input, overlay: overlay, digest: digest).freeze]
      end
    end
  end
end
