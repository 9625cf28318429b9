# frozen_string_literal: true

require_relative "release_spec"
require_relative "catalog/release_catalog"
require_relative "catalog/cache"
require_relative "project"
require_relative "plan/target"
require_relative "plan/ancestor"
require_relative "plan/inventory"
require_relative "plan/planner"
require_relative "plan/lock"
require_relative "plan/lock_parser"
require_relative "plan/lock_generator"
require_relative "plan/settlement"
require_relative "plan/gem_check"

module Relspec
  # The release plan (docs/plan.md): for every target and package, inherit,
  # build or published, with causes; recorded in releases/<r>/lock.yml.
  module Plan
    # Everything one planning run produced. +lock+: the lock of this plan
    # (to be written by plan --write and compile); +previous+: the lock read
    # (nil when there was none or it was discarded); +work+: Target =>
    # {package => Settlement::Work} for the builds, what compile emits.
    Result = Struct.new(:resolution, :plan, :lock, :previous, :lock_path, :spec_digest, :own, :release_catalog,
                        :ancestors, :work, :project_root, keyword_init: true) do
      def lock_text
        LockGenerator.dump(lock)
      end

      def write_lock
        LockGenerator.write(lock_path, lock)
      end
    end

    # Plans the release of the spec at +path+. The project root (where
    # releases/ lives) is the folder above the spec's folder. +timeout+ is the
    # HTTP timeout in seconds; +cache_dir+ holds downloaded indices (nil: none).
    # +discard_lock+: start without the lock's history when it cannot be read.
    def self.compute(path, timeout: 10, cache_dir: Apt::Cache.default_dir, catalog_cache: Catalog::Cache.new,
                     discard_lock: false)
      resolution = ReleaseSpec.resolve(path)
      effective = resolution.effective
      lock_path = Lock.path(project_root(path), effective.release)
      previous = read_lock(lock_path, effective.release, discard_lock)
      gem_fetch = Catalog::ReleaseGems.fetcher(effective, File.dirname(resolution.spec_file.path), timeout: timeout)
      cache = Apt::Cache.new(cache_dir)
      fetcher_options = { timeout: timeout }
      targets = Target.all(effective)
      gem_distribution = nil
      gem_archives = lambda do
        gem_distribution ||= read_distribution(resolution, Debian::Naming::DISTRIBUTION_GEMS, targets, fetcher_options, cache)
        targets.to_h { |target| [target.to_s, gem_distribution.index(target)] }
      end
      release_catalog = Catalog::ReleaseCatalog.load(resolution, cache: catalog_cache, gem_fetch: gem_fetch, timeout: timeout,
                                                                 gem_archives: gem_archives, locked_gems: locked_gems(previous))
      ancestors = Ancestors.of(resolution, fetcher_options: fetcher_options, cache: cache)
      inventory = Inventory.read(ancestors, targets)
      own = read_own(resolution, targets, fetcher_options, cache)
      GemCheck.call(previous, release_catalog, resolution)
      distribution = gem_distribution || read_distribution(resolution, wanted_of(release_catalog), targets, fetcher_options,
                                                           cache)
      planner = Planner.new(release_catalog: release_catalog, effective: effective, spec_file: resolution.spec_file,
                            ancestors: ancestors, inventory: inventory, distribution: distribution)
      root = project_root(path)
      plan, work = settle(planner.plan, release_catalog, effective, ancestors, own, previous, root)
      spec_digest = Lock.spec_digest(effective)
      Result.new(resolution: resolution, plan: plan, lock: Lock.from_plan(plan, spec_digest, previous&.history || History.empty),
                 previous: previous, lock_path: lock_path, spec_digest: spec_digest, own: own,
                 release_catalog: release_catalog, ancestors: ancestors, work: work, project_root: root)
    end

    # The use case's entry, shaped as Compile.run, Builder.run, Publish.run,
    # Availability.run and Diff.run: what the CLI calls.
    def self.run(path, **options)
      compute(path, **options)
    end

    # The folder above the spec's folder (where releases/ and overlays/ are),
    # as the user would write it.
    def self.project_root(path)
      Project.of_spec(path).root
    end

    # The lock, strictly read: one that cannot be read stops the run unless
    # the user chose to discard it (its history is then lost, and the
    # repository alone keeps revisions from being given twice).
    def self.read_lock(lock_path, release, discard)
      LockParser.read(lock_path, release: release)
    rescue LockError
      raise unless discard

      nil
    end

    def self.settle(plan, release_catalog, effective, ancestors, own, previous, root)
      inputs = DebianInputs.new(effective: effective, ancestors: ancestors, release_catalog: release_catalog)
      versioning = Versioning.new(history: previous&.history || History.empty, own: own)
      targets, work = Settlement.new(catalog: release_catalog.catalog, inputs: inputs, versioning: versioning,
                                     project_root: root).call(plan.targets)
      [plan.with_targets(targets), work]
    end

    # The gem versions the lock recorded (from the .gem's URL: the lock's
    # version is the Debian form), kept while they fit.
    def self.locked_gems(previous)
      (previous&.packages || {}).filter_map do |name, record|
        version = record["url"].to_s[%r{(?:\A|/)#{Regexp.escape(name)}-([^/]+)\.gem\z}, 1]
        [name, version] if version
      end.to_h
    end

    # The Debian names of the gems of the release and their dependencies.
    def self.wanted_of(release_catalog)
      needed = release_catalog.gems.values.flat_map { |archive| archive.runtime_dependencies.map(&:first) }
      (release_catalog.gems.keys + needed).uniq.map { |name| Debian::Naming.distribution_gem(name) }
    end

    # The targets' own ruby-* packages (+wanted+: names, or a Regexp).
    def self.read_distribution(resolution, wanted, targets, fetcher_options, cache)
      effective = resolution.effective
      origin = effective.origin("distributions")
      location = origin&.location || resolution.spec_file.location(["release"])
      DistributionPackages.read(effective.distributions, targets, wanted, spec_dir: File.dirname(resolution.spec_file.path),
                                                                          location: location, fetcher_options: fetcher_options, cache: cache)
    end

    def self.read_own(resolution, targets, fetcher_options, cache)
      entry = resolution.effective.repository
      return OwnRepository.read(nil, targets) unless entry

      spec_file = resolution.spec_file
      repository = Ancestors.reader(entry, entry.own_location, fetcher_options, cache)
      OwnRepository.read(repository, targets)
    rescue Apt::Repository::Error => e
      raise InvalidInput, [Diagnostic.error("own-repository", "the repository of #{resolution.effective.release}: #{e.message}",
                                            location: spec_file.key_location(["repository"]))]
    end
    private_class_method :read_own, :read_distribution, :locked_gems, :wanted_of, :read_lock, :settle
  end
end
