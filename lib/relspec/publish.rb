# frozen_string_literal: true

require "fileutils"
require_relative "release_specs"
require_relative "apt/opening"
require_relative "plan/inventory"
require_relative "atomic_file"
require_relative "diagnostic"
require_relative "osdeps/files"
require_relative "output_tree"
require_relative "project"
require_relative "target_build"
require_relative "builder/target_lock"
require_relative "reprepro/config"
require_relative "publish/repository_lock"
require_relative "publish/stale_reprepro_lock"
require_relative "publish/transaction"
require_relative "publish/live_lock"
require_relative "publish/upload"
require_relative "publish/inclusion_check"
require_relative "publish/pool_guard"
require_relative "reprepro/runner"
require_relative "publish/signing_key"
require_relative "publish/locked_release"
require_relative "publish/kept_builds"
require_relative "publish/held_packages"
require_relative "report"
require_relative "abi/published_dumps"
require_relative "unlinked_path"
require_relative "abi/rebuilt_dumps"

module Relspec
  # `relspec publish`: the built packages of a release into its reprepro
  # repository (spec `repository.path`), then the osdeps files of what the
  # repository really holds. Declarative and idempotent: the configuration
  # follows the spec, publishing the same results again changes nothing, and
  # a run interrupted anywhere is finished by the next one.
  module Publish
    # The folder of the repository that holds the release's status page.
    REPORT_DIR = "report"
    # The folder of the repository that holds its osdeps files (Osdeps::Files).
    OSDEPS_DIR = "osdeps"

    # Per target: +published+ the sources included now, +held+ those the
    # repository had already, +left_out+ the failed/skipped entries, +built+
    # false when the target has no build-results.yml.
    TargetResult = Struct.new(:target, :results_path, :published, :held, :left_out, :built, keyword_init: true)
    # +stale_lock+: reprepro's lock file a killed reprepro had left, removed
    # before publishing (nil: there was none); +recovered+: what became of
    # an interrupted publish's work (Transaction#recover; nil: none).
    # +report+: the status page written next to the repository (Report).
    # +abi_rebuilt+: the ABI indices that could not be read and were made
    # again (Abi::RebuiltDumps), none when every index was read.
    Result = Struct.new(:release, :repository, :targets, :osdeps_written, :osdeps_missing, :stale_lock, :recovered,
                        :report, :abi_rebuilt, keyword_init: true)

    # +target+: "codename/arch" or nil (all targets); +waiting+: called
    # when another publisher holds the repository.
    def self.run(path, out:, target: nil, timeout: 10, waiting: nil)
      resolution = ReleaseSpec.resolve(path)
      effective = resolution.effective
      repository = repository_path(resolution)
      tree = OutputTree.new(out, effective.release)
      all = Target.all(effective)
      selected = Target.select(target, all, effective.release)
      # No build of these targets runs while their results are read and included.
      holding(built_folders(tree, selected)) do
        locked = LockedRelease.read(resolution, path, timeout: timeout)
        # Each target's last build, read once: what is published, and what
        # the status page and its ABI verdicts describe.
        builds = all.map { |one| TargetBuild.read(tree, one) }
        # The status page, served with the repository (every target, the
        # failures too): its inputs read before the repository is touched,
        # so that a damaged one stops the publication, not half of it.
        page, logs = Report.of(resolution, Project.of_spec(path), locked.lock, builds)
        Report.check(logs, File.join(repository, REPORT_DIR), "html")
        results = results_of(builds.select { |build| selected.include?(build.target) }, tree, explicit: !target.nil?)
        locked = KeptBuilds.new(locked, results, builds.to_h { |build| [build.target, build.plan] }, Project.of_spec(path))
        result = include_and_render(locked, results, effective, repository, all, waiting: waiting)
        result.report = Report.write(page, logs, File.join(repository, REPORT_DIR), "html")
        result
      end
    end

    # The folders of +targets+ that a build wrote into.
    def self.built_folders(tree, targets)
      targets.map { |one| tree.target_dir(one) }.select { |dir| File.directory?(dir) }
    end

    # Holds the target lock of each of +folders+ (shared with other
    # publishers, never with a build), then yields.
    def self.holding(folders, &block)
      return yield if folders.empty?

      Builder::TargetLock.hold(folders.first, "publish", shared: true) { holding(folders.drop(1), &block) }
    end

    # +results+: target => its Builder::BuildResults at the planned
    # versions (nil: not built); +locked+: the LockedRelease the osdeps
    # files are listed from.
    def self.include_and_render(locked, results, effective, repository, all, waiting:)
      uploads = uploads(results, debug_symbols: effective.repository.debug_symbols)
      sign_with = effective.repository.sign_with
      SigningKey.check(sign_with) if sign_with
      config = Reprepro::Config.new(label: effective.release, description: "#{effective.release} for %<codename>s",
                                    targets: all, source: true, sign_with: sign_with)
      check_links(repository, results)
      RepositoryLock.hold(repository, waiting: waiting) do
        # read before anything is published: a damaged index is made again
        # here, never found after the packages are in
        dumps, rebuilt = published_dumps(repository, results, effective.release)
        locked.check { open_own(effective, repository) } # a kept version the repository lost is refused before any include
        stale_lock, recovered, targets = transaction(repository, waiting: waiting) do |dirs, recovered_now|
          include_targets(repository, dirs, config, results, uploads, export: recovered_now == :abandoned)
        end
        write_abi_dumps(repository, results, dumps)
        locked = locked.record(effective)
        written, missing = write_osdeps(locked, effective, repository)
        Result.new(release: effective.release, repository: repository, targets: targets, osdeps_written: written,
                   osdeps_missing: missing, stale_lock: stale_lock, recovered: recovered,
                   abi_rebuilt: rebuilt)
      end
    end

    # Nothing publish writes beside the apt repository (the ABI dumps, the
    # osdeps files) goes through a link it did not make: into the folder it
    # leads to, it would overwrite that folder's files. Asked before the
    # repository is touched.
    def self.check_links(repository, results)
      results.each { |target, read| Abi::PublishedDumps.check(repository, target, read.built) if read }
      UnlinkedPath.check(repository, OSDEPS_DIR, error: PublishError,
                                                 why: "publish writes its osdeps files only inside #{repository} and " \
                                                      "never through a link; remove the link and publish again")
    end

    # Per target, the Upload of each built package (none when unbuilt),
    # checked against its record; +debug_symbols+: with the -dbgsym .debs.
    def self.uploads(results, debug_symbols:)
      results.to_h do |target, read|
        [target, read ? read.built.map { |entry| Upload.of(entry, File.dirname(read.path), read.path, debug_symbols: debug_symbols) } : []]
      end
    end

    # Under reprepro's lock on the live database: recovers what an
    # interrupted publish left, yields the folders of a new Transaction and
    # switches to them; then deletes the pool files nothing lists any more.
    # [stale lock removed, recovery, the block's result]
    def self.transaction(repository, waiting:)
      transaction = Transaction.new(repository)
      lock = LiveLock.new(repository, waiting: waiting)
      transaction.undo_half_rename
      stale = lock.take
      begin
        recovered = transaction.recover
        result = transaction.run { |dirs| yield dirs, recovered }
      ensure
        lock.release
      end
      Reprepro::Runner.new(repository, error: PublishError).deleteunreferenced
      [stale, recovered, result]
    end

    def self.repository_path(resolution)
      entry = resolution.effective.repository
      return entry.path if entry&.path

      location = entry ? resolution.spec_file.key_location(["repository"]) : resolution.spec_file.location(["release"])
      raise InvalidInput, [Diagnostic.error("publish-repository",
                                            "release #{resolution.effective.release} has no repository.path to publish into",
                                            location: location, hint: "add `repository: { path: <reprepro base directory> }`")]
    end

    # target => the results of each of +builds+ (TargetBuild), nil when it
    # was not built (an error when the user named the target; +explicit+),
    # and an error when none was.
    def self.results_of(builds, tree, explicit:)
      release = tree.release
      results = builds.to_h do |build|
        path = tree.results_file(build.target)
        raise PublishError, "#{build.target} of #{release} has not been built: #{path} does not exist (run relspec build)" \
          if explicit && !build.built?

        [build.target, build.results]
      end
      return results if results.values.any?

      raise PublishError, "nothing to publish: no target of #{release} has a build-results.yml under " \
                          "#{tree.release_dir} (run relspec build first)"
    end

    # +dirs+: the Transaction's conf, db and dists folders; +export+: write
    # dists/ again even if the configuration is unchanged (a database put
    # back may have been changed by hand since).
    def self.include_targets(repository, dirs, config, results, uploads, export:)
      reprepro = Reprepro::Runner.new(repository, dirs, error: PublishError)
      changed = config.write(dirs.fetch(:conf))
      PoolGuard.check(repository, uploads.values.flatten.flat_map(&:items),
                      published: Dir.empty?(dirs.fetch(:db)) ? [] : reprepro.pool_files)
      targets = results.map do |target, read|
        listed = Dir.empty?(dirs.fetch(:db)) ? [] : reprepro.packages(target.codename)
        held, fresh = uploads[target].partition { |upload| listed.include?([upload.source, upload.version, "source"]) }
        fresh.each { |upload| reprepro.includedsc(target.codename, upload.dsc) }
        # Every .deb of the target in one call, held ones too: reprepro skips
        # what it has, and a run interrupted after a source was included but
        # before its .debs were gets them now.
        debs = uploads[target].flat_map(&:debs)
        reprepro.includedeb(target.codename, debs) unless debs.empty?
        InclusionCheck.new(target, reprepro.packages(target.codename)).check(uploads[target])
        TargetResult.new(target: target, results_path: read&.path, published: fresh.map(&:source), held: held.map(&:source),
                         left_out: read ? read.entries.reject { |record| record.built? || record.kept? } : [],
                         built: !read.nil?)
      end
      # A new or changed configuration reaches dists/ (distributions without
      # packages, a new signing key) only by an export.
      reprepro.export if changed || export
      targets
    end

    # Per built target, the ABI dumps the repository lists (an
    # Abi::PublishedDumps): its index, or, when the index cannot be read,
    # the dump files there that a record of the target's build-results.yml
    # (every record, not only this plan's) vouches for (Abi::RebuiltDumps).
    # [target => PublishedDumps, the RebuiltDumps made]
    def self.published_dumps(repository, results, release)
      rebuilt = []
      dumps = results.filter_map do |target, read|
        next unless read

        [target, Abi::PublishedDumps.read(repository, target)]
      rescue InvalidInput => e
        records = Builder::BuildResults.read(read.path, release: release, target: target).built
        rebuilt << Abi::RebuiltDumps.of(repository, target, records, problem: e.message.lines.first.strip)
        [target, rebuilt.last.dumps]
      end.to_h
      [dumps, rebuilt]
    end

    # The ABI dumps of the built libraries beside the apt repository
    # (Abi::PublishedDumps), verified with the other files by Upload, over
    # +dumps+ (published_dumps).
    def self.write_abi_dumps(repository, results, dumps)
      results.each do |target, read|
        next unless read

        Abi::PublishedDumps.write(repository, target, File.dirname(read.path), read.built, current: dumps.fetch(target))
      end
    end

    # <repository>/osdeps/<release>-<arch>.yml of the locked decisions the
    # repository (read as it is now, after the includes) or the ancestors
    # really hold.
    def self.write_osdeps(locked, effective, repository)
      listing = HeldPackages.list(locked.lock, own: open_own(effective, repository), inventory: locked.inventory)
      written = Osdeps::Files.write_release(listing.targets, effective, File.join(repository, OSDEPS_DIR))
      [written.changed_count, listing.missing]
    end

    # What the release's repository holds now (Plan::OwnRepository).
    def self.open_own(effective, repository)
      Plan::OwnRepository.read(Apt::Opening.repository(effective.repository, repository), Target.all(effective))
    end

    private_class_method :open_own, :check_links, :uploads, :transaction, :repository_path, :results_of, :include_targets,
                         :write_osdeps,
                         :write_abi_dumps
  end
end
