# frozen_string_literal: true

require_relative "plan"
require_relative "availability"
require_relative "debian/source_package"
require_relative "debian/package_version"
require_relative "osdeps/renderer"
require_relative "yaml/writer"
require_relative "atomic_file"

module Relspec
  # `relspec compile`: plan the release, then turn every build decision into
  # a Debian source package under <out>/<release>/<codename>-<arch>/<source>/,
  # write plan.yml per target for the builder, the lock (with the digest of
  # each generated debian/, from which revisions follow) and the osdeps files.
  # Only what changed is written.
  class Compile
    # +unchecked+: Availability::Report::TargetResults of the targets whose
    # OS dependencies could not be checked (no source, nothing cached).
    Result = Struct.new(:release, :written, :unchanged, :published, :lock_path, :lock_changed, :osdeps_written,
                        :unchecked, keyword_init: true)

    # +progress+ is called with (done, total) after each source package.
    # +check+: run the availability check first (Availability.guard, with
    # these options when a Hash) and refuse a release whose OS dependencies
    # are missing; false skips it.
    def self.run(path, out:, jobs: 2, timeout: 10, progress: nil, check: true)
      new(path, out, jobs, timeout, progress, check).run
    end

    def initialize(path, out, jobs, timeout, progress = nil, check = true)
      @path = path
      @out = out
      @jobs = [jobs.to_i, 1].max
      @timeout = timeout
      @progress = progress
      @check = check
    end

    def run
      @planned = Plan.compute(@path, timeout: @timeout)
      @effective = @planned.resolution.effective
      require_maintainer
      require_workspace
      availability = @check ? Availability.guard(@planned, timeout: @timeout, **(@check.is_a?(Hash) ? @check : {})) : nil
      @catalog = @planned.release_catalog.catalog
      @previous = @planned.recorded
      @project_root = Plan.project_root(@path)
      decisions, jobs, published = prepare
      written, unchanged = emit(jobs)
      plan = @planned.plan.with_targets(decisions)
      write_build_plans(plan)
      lock_changed = Plan::Lock.write(@planned.lock_path, plan, @planned.spec_digest)
      Result.new(release: @effective.release, written: written, unchanged: unchanged, published: published,
                 lock_path: @planned.lock_path, lock_changed: lock_changed, osdeps_written: write_osdeps(plan),
                 unchecked: availability ? availability.unchecked : [])
    end

    private

    def require_maintainer
      return if @effective["maintainer"]

      raise InvalidInput, [Diagnostic.error("missing-maintainer", "release #{@effective.release} names no maintainer",
                                            location: @planned.resolution.spec_file.location(["release"]),
                                            hint: "add `maintainer: Name <address>` (or inherit it from a parent)")]
    end

    def require_workspace
      workspace = @planned.release_catalog.workspace
      return unless Catalog::SnapshotSource.snapshot?(workspace)

      raise InvalidInput, [Diagnostic.error("snapshot-workspace",
                                            "compile needs the package checkouts, but #{workspace} is a catalog snapshot",
                                            location: @planned.resolution.spec_file.location(["workspace"]),
                                            hint: "point `workspace:` at the autoproj workspace to compile")]
    end

    # Decides final versions target by target, dependencies first, and lists
    # the source packages to emit: [decisions, [[dir, SourcePackage]], published].
    def prepare
      jobs = []
      published = []
      decisions = @planned.plan.targets.to_h do |target, by_package|
        final = by_package.dup
        order(by_package).each do |name|
          decision = by_package[name]
          next if decision.inherit? || decision.system?

          final[name], job = finalize(target, decision, final)
          if final[name].published?
            published << [target, name]
          else
            jobs << job
          end
        end
        [target, final]
      end
      [decisions, jobs, published]
    end

    def finalize(target, decision, decisions)
      package = @catalog.package(decision.package)
      upstream = Debian::PackageVersion.upstream_of(decision.version)
      input = input_for(target, package, decision, upstream, decisions)
      overlay = Debian::Overlay.for(@project_root, package.name, arch: target.arch)
      digest = Digest::SHA256.hexdigest(Debian::DebianDir.digest(Debian::DebianDir.render(input, revision: "0")) +
                                        overlay.signature)
      revision = revision_for(target, decision, upstream, digest)
      version = Debian::PackageVersion.full(upstream, revision, target.codename)
      kind = @planned.own.version_of(decision.deb_name, target) == version ? :published : :build
      final = Plan::Decision.new(**decision.each_pair.to_h, kind: kind, version: version, debian_digest: digest).freeze
      job = source_package(input, version, revision, package, overlay, digest)
      [final, [File.join(@out, @effective.release, "#{target.codename}-#{target.arch}", decision.deb_name), job]]
    end

    # Same upstream version: the recorded revision if debian/ is the same,
    # one more if it changed. A new upstream version starts at 1.
    def revision_for(target, decision, upstream, digest)
      recorded = @previous.dig(target.to_s, decision.package)
      return 1 unless recorded

      old_upstream, old_revision = Debian::PackageVersion.split(recorded["version"])
      return 1 unless old_upstream == upstream

      recorded["debian_digest"] == digest || recorded["debian_digest"].nil? ? old_revision : old_revision + 1
    end

    def source_package(input, version, revision, package, overlay, digest)
      Debian::SourcePackage.new(
        input: input, files: -> { Debian::DebianDir.render(input, revision: revision) }, digest: digest, version: version,
        checkout: checkout_of(package), overlay: overlay,
        orig_cache: File.join(@out, @effective.release, ".orig"),
        substitutions: { "@RELSPEC_INSTALL_DIR@" => input[:install_dir], "@RELSPEC_RELEASE@" => @effective.release,
                         "@RELSPEC_PACKAGE@" => input[:deb_name] }
      )
    end

    def checkout_of(package)
      package.source_dir && File.join(@planned.release_catalog.workspace, package.source_dir)
    end

    def input_for(target, package, decision, upstream, decisions)
      os = package.os_dependencies_for(target.codename)
      {
        package: package, deb_name: decision.deb_name, upstream: upstream, codename: target.codename,
        release: @effective.release, maintainer: @effective["maintainer"], install_dir: install_dir_of(decision),
        dependencies: dependencies_of(package, decisions), apt: os.apt,
        gems: Debian::ControlRelations.distribution_gems(os, @planned.release_catalog.gems.keys),
        gem: @planned.release_catalog.gems[package.name]
      }
    end

    def dependencies_of(package, decisions)
      (package.dependencies + package.optional_dependencies).uniq.sort.filter_map do |name|
        decision = decisions[name]
        decision && { deb_name: decision.deb_name, version: decision.version, install_dir: install_dir_of(decision) }
      end
    end

    # The distribution's own packages install into the system: nil.
    def install_dir_of(decision)
      return nil if decision.system?

      if decision.inherit?
        ancestor = @planned.ancestors.find { |candidate| candidate.name == decision.ancestor }
        prefix_dir(ancestor.install_prefix, ancestor.name, ancestor.separate_prefixes, decision.deb_name)
      else
        prefix_dir(@effective["install_prefix"], @effective.release, @effective["separate_prefixes"] != false,
                   decision.deb_name)
      end
    end

    def prefix_dir(install_prefix, release, separate, deb_name)
      base = File.join(install_prefix, release)
      separate ? File.join(base, deb_name) : base
    end

    # Package names in dependency order (dependencies first, then by name).
    def order(by_package)
      pending = by_package.keys.sort
      done = {}
      ordered = []
      until pending.empty?
        ready = pending.select do |name|
          package = @catalog.package(name)
          (package.dependencies + package.optional_dependencies).all? { |dep| done[dep] || !by_package.key?(dep) }
        end
        ready = [pending.first] if ready.empty? # a cycle: keep going in name order
        ready.each do |name|
          ordered << name
          done[name] = true
        end
        pending -= ready
      end
      ordered
    end

    def emit(jobs)
      queue = Queue.new
      jobs.each { |job| queue << job }
      written = []
      unchanged = []
      errors = []
      lock = Mutex.new
      failures = []
      Array.new([@jobs, jobs.size].min) do
        Thread.new do
          Thread.current.report_on_exception = false
          while (job = next_job(queue))
            dir, package = job
            begin
              changed = package.emit(dir)
              lock.synchronize do
                (changed ? written : unchanged) << dir
                @progress&.call(written.size + unchanged.size, jobs.size)
              end
            rescue InvalidInput => e
              lock.synchronize { errors.concat(e.diagnostics) }
            rescue StandardError => e # re-raised below, in the main thread, where errors become messages
              lock.synchronize { failures << e }
            end
          end
        end
      end.each(&:join)
      raise failures.first unless failures.empty?
      raise InvalidInput, errors unless errors.empty?

      [written.sort, unchanged.sort]
    end

    def next_job(queue)
      queue.pop(true)
    rescue ThreadError
      nil
    end

    # <out>/<release>/<codename>-<arch>/plan.yml: the builds in dependency
    # order, each with the packages built here that it needs first.
    def write_build_plans(plan)
      plan.targets.each do |target, decisions|
        builds = order(decisions).map { |name| decisions[name] }.select(&:build?)
        built = builds.to_h { |decision| [decision.package, decision] }
        entries = builds.map do |decision|
          package = @catalog.package(decision.package)
          needs = (package.dependencies + package.optional_dependencies).uniq.sort.filter_map { |dep| built[dep]&.deb_name }
          { "package" => decision.package, "source" => decision.deb_name, "version" => decision.version,
            "dsc" => "#{decision.deb_name}/#{decision.deb_name}_#{decision.version}.dsc", "build_depends" => needs }
        end
        dir = File.join(@out, @effective.release, "#{target.codename}-#{target.arch}")
        FileUtils.mkdir_p(dir)
        AtomicFile.update(File.join(dir, "plan.yml"),
                         Yaml::Writer.dump("release" => plan.release, "target" => target.to_s, "builds" => entries))
      end
    end

    def write_osdeps(plan)
      files = Osdeps::Renderer.render(plan, @effective.distributions)
      dir = File.join(File.dirname(@planned.lock_path), "osdeps")
      FileUtils.mkdir_p(dir)
      files.count do |arch, text|
        AtomicFile.update(File.join(dir, Osdeps::Renderer.file_name(@effective.release, arch)), text)
      end
    end
  end
end
