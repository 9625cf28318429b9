# frozen_string_literal: true

require_relative "spec"
require_relative "catalog/release_catalog"
require_relative "catalog/cache"
require_relative "display_path"
require_relative "plan/target"
require_relative "plan/ancestor"
require_relative "plan/inventory"
require_relative "plan/planner"
require_relative "plan/lock"
require_relative "plan/gem_check"

module Relspec
  # The release plan (DESIGN §3, §4): for every target and package, inherit,
  # build or published, with causes; recorded in releases/<r>/lock.yml.
  module Plan
    # Everything one planning run produced.
    # +recorded+: the builds the existing lock records (Lock.builds), read once.
    Result = Struct.new(:resolution, :plan, :lock_path, :spec_digest, :own, :release_catalog, :ancestors, :recorded,
                        keyword_init: true) do
      def lock_text
        Lock.dump(plan, spec_digest)
      end
    end

    # Plans the release of the spec at +path+. The project root (where
    # releases/ lives) is the folder above the spec's folder. +timeout+ is the
    # HTTP timeout in seconds; +cache_dir+ holds downloaded indices (nil: none).
    def self.compute(path, timeout: 10, cache_dir: Apt::Cache.default_dir, catalog_cache: Catalog::Cache.new)
      resolution = Spec.resolve(path)
      effective = resolution.effective
      gem_fetch = Catalog::ReleaseGems.fetcher(effective, File.dirname(resolution.spec_file.path), timeout: timeout)
      release_catalog = Catalog::ReleaseCatalog.load(resolution, cache: catalog_cache, gem_fetch: gem_fetch)
      cache = Apt::Cache.new(cache_dir)
      fetcher_options = { timeout: timeout }
      ancestors = Ancestors.of(resolution, fetcher_options: fetcher_options, cache: cache)
      targets = Target.all(effective)
      inventory = Inventory.read(ancestors, targets)
      own = read_own(resolution, targets, fetcher_options, cache)
      lock_path = Lock.path(project_root(path), effective.release)
      locked = Lock.read(lock_path)
      recorded = Lock.builds(locked)
      GemCheck.call(locked, release_catalog, resolution)
      distribution = read_distribution(resolution, release_catalog, targets, fetcher_options, cache)
      planner = Planner.new(release_catalog: release_catalog, effective: effective, spec_file: resolution.spec_file,
                            ancestors: ancestors, inventory: inventory, own: own, revisions: Lock.revisions(recorded),
                            distribution: distribution)
      Result.new(resolution: resolution, plan: with_recorded_builds(planner.plan, recorded), lock_path: lock_path,
                 recorded: recorded,
                 spec_digest: Lock.spec_digest(effective), own: own, release_catalog: release_catalog,
                 ancestors: ancestors)
    end

    # The folder above the spec's folder (where releases/ and overlays/ are),
    # as the user would write it.
    def self.project_root(path)
      DisplayPath.of(File.dirname(File.dirname(File.expand_path(path))))
    end

    # What the lock recorded of earlier builds stays: the debian/ digests of
    # the builds whose version did not change, and the last build of packages
    # not built now, so that writing the lock from `plan --write` never loses
    # what decides the next revision.
    def self.with_recorded_builds(plan, recorded)
      return plan if recorded.empty?

      last_builds = plan.targets.keys.to_h do |target|
        not_built = plan.targets.fetch(target).reject { |_, decision| decision.build? || decision.published? }.keys +
                    plan.unavailable.fetch(target).keys
        [target, recorded.fetch(target.to_s, {}).slice(*not_built)]
      end
      targets = plan.targets.to_h do |target, decisions|
        [target, decisions.transform_values do |decision|
          entry = recorded.dig(target.to_s, decision.package)
          next decision if decision.inherit? || entry.nil? || entry["version"] != decision.version || !entry["debian_digest"]

          Decision.new(**decision.each_pair.to_h, debian_digest: entry["debian_digest"]).freeze
        end]
      end
      plan.with_targets(targets, last_builds: last_builds.reject { |_, builds| builds.empty? })
    end

    # The targets' own ruby-* packages for the gems of the release.
    def self.read_distribution(resolution, release_catalog, targets, fetcher_options, cache)
      needed = release_catalog.gems.values.flat_map { |archive| archive.runtime_dependencies.map(&:first) }
      wanted = (release_catalog.gems.keys + needed).uniq.map { |name| Debian::Naming.distribution_gem(name) }
      effective = resolution.effective
      origin = effective.origin("distributions")
      location = origin&.location || resolution.spec_file.location(["release"])
      DistributionPackages.read(effective.distributions, targets, wanted, spec_dir: File.dirname(resolution.spec_file.path),
                                                                           location: location, fetcher_options: fetcher_options, cache: cache)
    end

    def self.read_own(resolution, targets, fetcher_options, cache)
      entry = resolution.effective["repository"]
      return OwnRepository.read(nil, targets) unless entry

      spec_file = resolution.spec_file
      # The release publishes into its path: a path that does not exist yet
      # is an empty repository, never a reason to ask the URL.
      entry = entry.except("url") if entry["path"]
      repository = Ancestors.reader(entry, File.dirname(spec_file.path), fetcher_options, cache)
      OwnRepository.read(repository, targets)
    rescue Apt::Repository::Error => e
      raise InvalidInput, [Diagnostic.error("own-repository", "the repository of #{resolution.effective.release}: #{e.message}",
                                            location: spec_file.key_location(["repository"]))]
    end
    private_class_method :read_own, :read_distribution, :with_recorded_builds
  end
end
