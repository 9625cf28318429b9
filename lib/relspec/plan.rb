# frozen_string_literal: true

require_relative "release_specs"
require_relative "catalog/release_catalog"
require_relative "catalog/uncommitted_changes"
require_relative "catalog/cache"
require_relative "cache_writer"
require_relative "project"
require_relative "plan/target"
require_relative "apt/opening"
require_relative "plan/inventory"
require_relative "plan/planner"
require_relative "plan/lock"
require_relative "plan/lock_parser"
require_relative "plan/lock_generator"
require_relative "plan/settlement"
require_relative "plan/gem_check"
require_relative "plan/gem_ruby_check"
require_relative "plan/gem_archives"
require_relative "debian/overlay"
require_relative "plan/facts"
require_relative "plan/result"

module Relspec
  # The release plan (docs/plan.md): for every target and package, inherit,
  # build or published, with causes; recorded in releases/<r>/lock.yml.
  module Plan
    # Plans the release of the spec at +path+: Plan.decide over Plan.read.
    # Returns a Result. The use case's entry, shaped as Compile.run,
    # Builder.run, Publish.run, Availability.run and Diff.run: what the CLI
    # calls.
    def self.run(path, timeout: 10, cache_dir: Apt::Cache.default_dir, cache_writer: CacheWriter.new,
                 catalog_cache: Catalog::Cache.new(writer: cache_writer), discard_lock: false)
      decide(read(path, timeout: timeout, cache_dir: cache_dir, cache_writer: cache_writer, catalog_cache: catalog_cache,
                        discard_lock: discard_lock))
    end

    # Everything planning reads (Facts): the spec hierarchy, the workspace,
    # the ancestors' and the release's repositories, the distribution's gems
    # and the lock. The project root (where releases/ and overlays/ live) is
    # the folder above the spec's folder. +timeout+ is the HTTP timeout in
    # seconds; +cache_dir+ holds downloaded indices (nil: none).
    # +discard_lock+: start without the lock's history when it cannot be read.
    # +cache_writer+: the CacheWriter of every cache the run writes (a cache
    # that cannot be written is noted once, and planning goes on).
    def self.read(path, timeout: 10, cache_dir: Apt::Cache.default_dir, cache_writer: CacheWriter.new,
                  catalog_cache: Catalog::Cache.new(writer: cache_writer), discard_lock: false)
      resolution = ReleaseSpec.resolve(path)
      effective = resolution.effective
      lock_path = Lock.path(project_root(path), effective.release)
      previous = read_lock(lock_path, effective.release, discard_lock)
      gem_fetch = Catalog::ReleaseGems.fetcher(effective, File.dirname(resolution.spec_file.path), timeout: timeout)
      cache = Apt::Cache.new(cache_dir, writer: cache_writer)
      fetcher_options = { timeout: timeout }
      targets = Target.all(effective)
      gem_archives = GemArchives.new(targets) do |wanted|
        read_distribution(resolution, wanted, targets, fetcher_options, cache)
      end
      release_catalog = Catalog::ReleaseCatalog.load(resolution, cache: catalog_cache, gem_fetch: gem_fetch, timeout: timeout,
                                                                 gem_archives: gem_archives, locked_gems: locked_gems(previous))
      ancestors = resolution.lineage.opened_ancestors(fetcher_options: fetcher_options, cache: cache)
      inventory = Inventory.read(ancestors, targets)
      own = read_own(resolution, targets, fetcher_options, cache)
      GemCheck.call(previous, release_catalog, resolution)
      distribution = gem_archives.distribution(wanted_of(release_catalog))
      root = project_root(path)
      Facts.new(resolution: resolution, release_catalog: release_catalog, ancestors: ancestors, inventory: inventory,
                distribution: distribution, own: own, previous: previous, lock_path: lock_path, project_root: root,
                overlays: lambda { |name, target|
                  Debian::Overlay.for(root, name, arch: target.arch, codename: target.codename)
                },
                uncommitted: uncommitted_of(release_catalog))
    end

    # The selected checkouts' changes beyond their commits (none from a snapshot).
    def self.uncommitted_of(release_catalog)
      workspace = release_catalog.workspace
      return {} if Catalog::SnapshotSource.snapshot?(workspace)

      names = release_catalog.selections.values.flat_map(&:names).uniq
      Catalog::UncommittedChanges.read(workspace, names.map { |name| release_catalog.catalog.package(name) })
    end

    # The decisions over what was read (+facts+: Facts), versions settled,
    # and the lock that records them. Reads nothing but the overlays.
    def self.decide(facts)
      resolution = facts.resolution
      effective = resolution.effective
      planner = Planner.new(release_catalog: facts.release_catalog, effective: effective, spec_file: resolution.spec_file,
                            ancestors: facts.ancestors, inventory: facts.inventory, distribution: facts.distribution,
                            uncommitted: facts.uncommitted || {})
      decided = planner.plan
      GemRubyCheck.call(decided, facts.release_catalog, resolution)
      plan, work = settle(decided, facts)
      history = facts.previous&.history || History.empty
      Result.new(resolution: resolution, release_catalog: facts.release_catalog, plan: plan,
                 lock: Lock.from_plan(plan, Lock.spec_digest(effective), history), lock_path: facts.lock_path, work: work,
                 lock_read: !facts.previous.nil?, project_root: facts.project_root)
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

    def self.settle(plan, facts)
      inputs = DebianInputs.new(effective: facts.resolution.effective, ancestors: facts.ancestors,
                                release_catalog: facts.release_catalog)
      history = facts.previous&.history || History.empty
      versioning = Versioning.new(history: history, own: facts.own)
      rising = RisingUpstream.new(history: history, own: facts.own)
      targets, work, raised = Settlement.new(catalog: facts.release_catalog.catalog, inputs: inputs, versioning: versioning,
                                             overlays: facts.overlays, rising: rising).call(plan.targets)
      [plan.with_targets(targets, warnings: raised_warnings(raised, facts.resolution.spec_file)), work]
    end

    # One warning per package whose version was raised (RisingUpstream),
    # listing the targets.
    def self.raised_warnings(raised, spec_file)
      raised.group_by { |one| [one.package, one.given, one.above, one.upstream, one.import] }.sort_by { |key, _| key.first(4) }
            .map do |(package, given, above, upstream, import), all|
        targets = all.map { |one| one.target.to_s }.uniq.sort.join(", ")
        upgrade = "versioned #{upstream}, so that apt takes it as an upgrade"
        if import
          Diagnostic.warning("archive-time-back",
                             "#{package}: its archive's time gives #{given}, below #{above}, which the release already " \
                             "gave it (#{targets}); #{upgrade}",
                             location: spec_file.location(["workspace"]),
                             hint: "an older archive is served again: check the package set's url, or leave it so")
        else
          Diagnostic.warning("version-back",
                             "#{package}: its version #{given} is below #{above}, which the release already gave it " \
                             "(#{targets}); #{upgrade} (reprepro and apt never take a lower one)",
                             location: spec_file.location(["workspace"]),
                             hint: "a pin or a commit moved back on purpose: leave it so")
        end
      end
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
      repository = Apt::Opening.repository(entry, entry.own_location, fetcher_options: fetcher_options, cache: cache)
      OwnRepository.read(repository, targets)
    rescue Apt::Repository::Error => e
      raise InvalidInput, [Diagnostic.error("own-repository", "the repository of #{resolution.effective.release}: #{e.message}",
                                            location: spec_file.key_location(["repository"]))]
    end
    private_class_method :read_own, :read_distribution, :locked_gems, :wanted_of, :read_lock, :settle
  end
end
