# frozen_string_literal: true

require "digest"
require "fileutils"
require "json"
require_relative "../yaml/writer"
require_relative "../yaml/located_document"
require_relative "../atomic_file"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # releases/<release>/lock.yml (DESIGN §6): what a plan decided and what it
    # read to decide it. Deterministic: keys sorted, no timestamps, no host
    # paths; writing the same plan twice gives the same bytes. Lock files are
    # the reviewable record of a release, so `relspec diff` compares them.
    module Lock
      FORMAT_KEY = "relspec_lock"
      FORMAT_VERSION = 1

      module_function

      def path(root, release)
        root == "." ? File.join("releases", release, "lock.yml") : File.join(root, "releases", release, "lock.yml")
      end

      def to_h(plan, spec_digest)
        {
          FORMAT_KEY => FORMAT_VERSION, "release" => plan.release, "spec_digest" => spec_digest,
          "ancestors" => ancestors(plan), "packages" => plan.packages.sort.to_h,
          "targets" => plan.targets.sort_by { |target, _| target.to_s }.to_h do |target, decisions|
            entries = decisions.transform_values(&:to_h)
            plan.unavailable.fetch(target).each do |name, cause|
              entries[name] = { "decision" => "unavailable", "causes" => cause.chain }
            end
            plan.last_builds.fetch(target, {}).each do |name, build|
              entries[name] = entries[name].merge("last_build" => build) if entries[name]
            end
            [target.to_s, entries.sort.to_h]
          end,
          "warnings" => plan.warnings.map(&:message), "notes" => plan.notes
        }
      end

      def dump(plan, spec_digest)
        Yaml::Writer.dump(to_h(plan, spec_digest))
      end

      def write(path, plan, spec_digest)
        FileUtils.mkdir_p(File.dirname(path))
        AtomicFile.update(path, dump(plan, spec_digest))
      end

      def ancestors(plan)
        plan.release_digests.keys.map(&:first).uniq.sort.to_h do |name|
          digests = plan.release_digests.select { |(ancestor, _), _| ancestor == name }
          [name, digests.map { |(_, codename), digest| [codename, digest] }.sort.to_h]
        end
      end

      # The digest of what the spec means (its effective values), so a lock
      # records which spec it was planned from.
      def spec_digest(effective)
        Digest::SHA256.hexdigest(JSON.generate(effective.to_h))
      end

      BUILT = %w[build published].freeze

      # "codename/arch" => {package => {"version", "debian_digest"}} of the
      # builds an existing lock's +data+ (read) records: this release's builds,
      # and the last build of packages it did not build that time.
      def builds(data)
        return {} unless data

        data.fetch("targets", {}).transform_values do |decisions|
          decisions.each_with_object({}) do |(name, decision), out|
            build = BUILT.include?(decision["decision"]) ? decision : decision["last_build"]
            out[name] = build.slice("version", "debian_digest") if build.is_a?(Hash) && build["version"]
          end
        end
      end

      def read(path)
        return nil unless File.file?(path)

        document = Yaml::LocatedDocument.load(path)
        data = document.data
        document.ok? && data.is_a?(Hash) && data[FORMAT_KEY] == FORMAT_VERSION ? data : nil
      end

      # "codename/arch" => package => {upstream version => revision} from the
      # builds of an existing lock (see builds), so that a package keeps its revision on each target from
      # plan to plan (compile decides revisions per target).
      def revisions(builds)
        builds.transform_values do |decisions|
          decisions.each_with_object({}) do |(name, decision), out|
            upstream, revision = Debian::PackageVersion.split(decision["version"])
            out[name] = { upstream => revision } if upstream
          end
        end
      end
    end
  end
end
