# frozen_string_literal: true

require_relative "plan"
require_relative "availability"
require_relative "debian/source_package"
require_relative "debian/emitter"
require_relative "debian/naming"
require_relative "osdeps/files"
require_relative "output_tree"
require_relative "project"
require_relative "yaml/writer"
require_relative "builder/build_plan"
require_relative "catalog/archive_import"
require_relative "cache_dir"
require_relative "atomic_file"
require_relative "temporaries"

module Relspec
  # `relspec compile`: plan the release, then turn every build decision into
  # a Debian source package under <out>/<release>/<codename>-<arch>/<source>/,
  # write plan.yml per target for the builder, the lock (with the digest of
  # each generated debian/, from which revisions follow) and the osdeps files.
  # Only what changed is written.
  class Compile
    # +unchecked+: Availability::Report::TargetResults of the targets whose
    # OS dependencies could not be checked (no source, nothing cached).
    # +repaired+: orig cache entries found damaged and made again.
    Result = Struct.new(:release, :written, :unchanged, :published, :lock_path, :lock_changed, :osdeps_written,
                        :unchecked, :repaired, keyword_init: true)

    # +progress+ is called with (done, total) after each source package.
    # +discard_lock+: go on without a lock that cannot be read.
    # +check+: run the availability check first (Availability.guard, with
    # these options when a Hash) and refuse a release whose OS dependencies
    # are missing; false skips it.
    # +planned+ (optional) is called with the Plan::Result before anything
    # is written.
    def self.run(path, out:, jobs: 2, timeout: 10, progress: nil, discard_lock: false, check: true, planned: nil)
      new(path, out, jobs, timeout, progress, discard_lock: discard_lock, check: check, planned: planned).run
    end

    def initialize(path, out, jobs, timeout, progress = nil, discard_lock: false, check: true, planned: nil)
      @path = path
      @out = out
      @jobs = [jobs.to_i, 1].max
      @timeout = timeout
      @progress = progress
      @discard_lock = discard_lock
      @check = check
      @on_planned = planned
    end

    def run
      cache_writer = CacheWriter.new # one note for every cache the run cannot write
      @planned = Plan.run(@path, timeout: @timeout, cache_writer: cache_writer, discard_lock: @discard_lock)
      @on_planned&.call(@planned)
      @effective = @planned.effective
      @tree = OutputTree.new(@out, @effective.release)
      require_maintainer
      require_workspace
      availability = if @check
                       Availability.guard(@planned, timeout: @timeout, cache_writer: cache_writer,
                                                    **(@check.is_a?(Hash) ? @check : {}))
                     end
      @catalog = @planned.catalog
      plan = @planned.plan
      jobs, published = jobs_of(plan)
      sweep_temporaries
      emitted = Debian::Emitter.new(jobs: @jobs, progress: @progress).call(jobs)
      write_build_plans(plan)
      lock_changed = @planned.write_lock
      Result.new(release: @effective.release, written: emitted.written, unchanged: emitted.unchanged, published: published,
                 lock_path: @planned.lock_path, lock_changed: lock_changed, osdeps_written: write_osdeps(plan),
                 unchecked: availability ? availability.unchecked : [], repaired: emitted.repaired)
    end

    private

    def require_maintainer
      return if @effective.maintainer

      raise InvalidInput, [Diagnostic.error("missing-maintainer", "release #{@effective.release} names no maintainer",
                                            location: @planned.spec_location(["release"]),
                                            hint: "add `maintainer: Name <address>` (or inherit it from a parent)")]
    end

    def require_workspace
      workspace = @planned.workspace
      return unless Catalog::SnapshotSource.snapshot?(workspace)

      raise InvalidInput, [Diagnostic.error("snapshot-workspace",
                                            "compile needs the package checkouts, but #{workspace} is a catalog snapshot",
                                            location: @planned.spec_location(["workspace"]),
                                            hint: "point `workspace:` at the autoproj workspace to compile")]
    end

    # The source packages to emit, [[dir, SourcePackage]], and the builds the
    # repository already holds: versions are the plan's, never decided here.
    def jobs_of(plan)
      jobs = []
      published = []
      plan.targets.each do |target, decisions|
        decisions.each_value do |decision|
          published << [target, decision.package] if decision.published?
          next unless decision.build?

          dir = @tree.source_dir(target, decision.deb_name)
          jobs << [dir, source_package(@planned.work_for(target, decision.package), decision)]
        end
      end
      [jobs.sort_by(&:first), published]
    end

    def source_package(work, decision)
      input = work.input
      package = input.package
      Debian::SourcePackage.new(
        input: input, version: decision.version, digest: work.digest, checkout: checkout_of(package),
        overlay: work.overlay, orig_cache: @tree.orig_cache, archives: archives,
        substitutions: { "@RELSPEC_INSTALL_DIR@" => input.install_dir, "@RELSPEC_RELEASE@" => @effective.release,
                         "@RELSPEC_PACKAGE@" => input.deb_name }
      )
    end

    # The archives of archive imports, fetched once into the user's cache;
    # compile's --timeout reaches their download.
    def archives
      @archives ||= Catalog::ArchiveImport.new(cache: CacheDir.for("archives"), timeout: @timeout)
    end

    def checkout_of(package)
      package.source_dir && File.join(@planned.workspace, package.source_dir)
    end

    # Leftovers of compiles that were killed: removed before this one
    # writes, so that the tree ends as a clean compile's would.
    def sweep_temporaries
      orig = @tree.orig_cache
      [*Dir.glob(File.join(@tree.release_dir, "*/")), *Dir.glob(File.join(orig, "*/")), orig].each do |dir|
        Temporaries.sweep(dir)
      end
    end

    # The plan's early cutoff candidate (Plan::CutoffCandidate) as plan.yml
    # carries it: the dependencies by their source names.
    def cutoff_of(decision, built)
      return nil unless decision.cutoff

      Builder::BuildPlan::Cutoff.new(keeps: decision.cutoff.keeps.to_s,
                                     because: decision.cutoff.because.map { |name| built.fetch(name).deb_name },
                                     debian_digest: decision.cutoff.debian_digest,
                                     against: decision.cutoff.against)
    end

    # <out>/<release>/<codename>-<arch>/plan.yml: the builds in dependency
    # order, each with the packages built here that it needs first.
    def write_build_plans(plan)
      plan.targets.each do |target, decisions|
        builds = Plan::BuildOrder.of(@catalog, decisions.keys).map { |name| decisions[name] }.select(&:build?)
        built = builds.to_h { |decision| [decision.package, decision] }
        entries = builds.map do |decision|
          needs = @catalog.package(decision.package).build_dependencies.filter_map { |dep| built[dep]&.deb_name }
          Builder::BuildPlan::Entry.new(package: decision.package, source: decision.deb_name,
                                        version: decision.version.to_s, build_depends: needs,
                                        dsc: "#{decision.deb_name}/#{Debian::Naming.dsc(decision.deb_name, decision.version)}",
                                        cutoff: cutoff_of(decision, built))
        end
        FileUtils.mkdir_p(@tree.target_dir(target))
        Builder::BuildPlan.write(@tree.target_dir(target), release: plan.release, target: target, entries: entries)
      end
    end

    def write_osdeps(plan)
      dir = Project.new(@planned.project_root).osdeps_dir(@effective.release)
      Osdeps::Files.write_release(plan.targets, @effective, dir).changed_count
    end
  end
end
