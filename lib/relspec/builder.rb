# frozen_string_literal: true

require "digest"
require "fileutils"
require_relative "release_specs"
require_relative "error"
require_relative "target"
require_relative "output_tree"
require_relative "builder/build_plan"
require_relative "builder/build_results"
require_relative "builder/request"
require_relative "builder/target_lock"
require_relative "builder/repositories"
require_relative "builder/scheduler"
require_relative "builder/early_cutoff"
require_relative "builder/tool"
require_relative "builder/unlinked_path"
require_relative "builder/staged_results"
require_relative "builder/abi_dumper"
require_relative "builder/host_backend"
require_relative "builder/sbuild_backend"
require_relative "builder/slurm/cluster"
require_relative "builder/slurm/engine"
require_relative "builder/slurm/settings"
require_relative "builder/slurm/run"
require_relative "builder/slurm/job_evidence"

module Relspec
  # `relspec build`: builds the source packages `relspec compile` wrote,
  # per target in the order of its plan.yml, with one backend, and records
  # every package's outcome in <target folder>/build-results.yml (BuildResults).
  # Built files go to <target folder>/results/<source>/, logs to
  # <target folder>/logs/<source>.log. docs/build.md describes it.
  module Builder
    BACKENDS = %w[sbuild host].freeze
    ENGINES = %w[local slurm].freeze

    # Per target: +reused+ counts packages an earlier run built (files checked).
    TargetReport = Struct.new(:target, :dir, :results, :outcomes, :reused, :prepared, keyword_init: true) do
      def failed?
        outcomes.any? { |outcome| !Scheduler::SUCCESSES.include?(outcome.status) }
      end
    end

    # +targets+: ["codename/arch"] to build (default: every target of the
    # spec); +listener+: receives start(target, total, done), building(entry),
    # finished(outcome) for progress output. +engine+: "local" (the
    # Scheduler, --jobs at once) or "slurm" (Slurm::Engine with
    # +slurm_settings+); +notices+: where the Slurm engine says what it
    # cancelled. +verdicts+: how a run judges each finished build against
    # the one it replaces, called with (results, plan entries, target
    # folder) per target (the early cutoff's Abi::InterfaceVerdicts.of,
    # which the CLI hands in: abi/ reads builds, so builder/ does not
    # require it); none by default. +rebuild_dependents+: the early cutoff
    # keeps nothing in this run (every candidate is built).
    def self.run(path, out:, backend: "sbuild", jobs: 1, targets: nil, keep_going: false, rebuild: false,
                 prepare_only: false, listener: nil, engine: "local", slurm_settings: nil, notices: nil,
                 verdicts: NoVerdicts.method(:of), rebuild_dependents: false)
      Run.new(path, out: out, backend: backend, jobs: jobs, targets: targets, keep_going: keep_going,
                    rebuild: rebuild, prepare_only: prepare_only, listener: listener,
                    engine: engine, slurm_settings: slurm_settings, notices: notices, verdicts: verdicts,
                    rebuild_dependents: rebuild_dependents).call
    end

    # A run that judges no build: no interface verdict, no cutoff.
    module NoVerdicts
      module_function

      def of(*)
        self
      end

      def decide(*); end

      def deciding?
        false
      end

      def keep(_entry); end

      def revoke(*); end

      def [](_source); end

      def cutoff(_source); end
    end

    # One `relspec build` run.
    class Run
      def initialize(path, out:, backend:, jobs:, targets:, keep_going:, rebuild:, prepare_only:, listener:,
                     engine: "local", slurm_settings: nil, notices: nil, verdicts: NoVerdicts.method(:of),
                     rebuild_dependents: false)
        raise InvalidOption, "unknown engine #{engine.inspect} (known: #{ENGINES.join(', ')})" unless ENGINES.include?(engine)

        @engine = engine
        @slurm_settings = slurm_settings || Slurm::Settings.new({})
        @notices = notices
        @path = path
        @out = out
        @backend_name = backend
        @jobs = jobs
        @only = targets
        @keep_going = keep_going
        @rebuild = rebuild
        @prepare_only = prepare_only
        @listener = listener
        @tool = Tool.new
        @verdicts = verdicts
        @rebuild_dependents = rebuild_dependents
      end

      def call
        resolution = ReleaseSpec.resolve(@path)
        @effective = resolution.effective
        backend = make_backend
        tree = OutputTree.new(@out, @effective.release)
        lineage = resolution.lineage
        Target.select(@only, Target.all(@effective), @effective.release).map do |target|
          dir = File.expand_path(tree.target_dir(target))
          plan = BuildPlan.read(dir)
          TargetLock.hold(dir, "build") do
            refuse_links(dir, plan)
            FileUtils.mkdir_p(File.join(dir, OutputTree::LOGS_DIR))
            prepare_log = UnlinkedPath.check(dir, OutputTree::PREPARE_LOG)
            # on a cluster the chroot-prepare job of the target makes it, on a node
            prepared = slurm? && !@prepare_only ? false : backend.prepare(target, log: prepare_log)
            next TargetReport.new(target: target, dir: dir, outcomes: [], reused: 0, prepared: prepared) if @prepare_only

            report = build_target(target, dir, plan, backend, Repositories.of(lineage, target.codename), prepared)
            # its builds have ended: the next target starts with what they held freed
            backend.finish_target(target)
            report
          end
        end
      rescue Interrupt
        @tool.stop_all
        raise
      ensure
        backend&.finish
      end

      private

      def make_backend
        case @backend_name
        when "host" then HostBackend.new(@tool)
        when "sbuild" then SbuildBackend.new(@tool, @effective.distributions, chroot_cache: shared_chroots)
        else raise BuildError, "unknown backend #{@backend_name.inspect} (known: #{BACKENDS.join(', ')})"
        end
      end

      # Every path the run writes below +dir+, checked before the first
      # build starts (UnlinkedPath).
      def refuse_links(dir, plan)
        %w[results logs logs/prepare.log].each { |relative| UnlinkedPath.check(dir, relative) }
        plan.entries.each do |entry|
          UnlinkedPath.check(dir, OutputTree.results_name(entry.source))
          UnlinkedPath.check(dir, OutputTree.log_name(entry.source))
        end
      end

      def slurm?
        @engine == "slurm"
      end

      # With Slurm, the chroot tarballs live in the shared folder when the
      # settings name one (every node of an architecture uses the same).
      def shared_chroots
        folder = slurm? && @slurm_settings["shared_folder"]
        folder ? File.join(File.expand_path(folder), "chroots") : nil
      end

      def build_target(target, dir, plan, backend, repositories, prepared)
        # Records of packages the plan does not build now stay in the file
        # (a narrowed selection widened again builds nothing twice).
        results = BuildResults.load(dir, release: @effective.release, target: target)
        digests = dsc_digests(plan)
        refused = refusal
        built, kept = earlier(results, plan, digests, backend, refused)
        done = (built + kept).map(&:source)
        @listener&.start(target, plan.entries.size, done.size)
        local = Mutex.new
        debs = built.flat_map { |entry| debs_of(dir, results[entry.source]) }
        evidence = slurm? ? job_evidence(plan, target, backend, results, built.map(&:source)) : nil
        verdicts = @verdicts.call(results, plan.entries, dir, refused: refused, replaced: evidence&.replaced&.root)
        cutoff = EarlyCutoff.new(verdicts, plan.entries, kept: kept.map(&:source))
        on_start = ->(entry) { @listener&.building(entry) }
        revoked = {}
        on_done = recorder(results, dir, digests, verdicts, cutoff, revoked, backend)
        outcomes = if slurm?
                     run_slurm(plan, target, backend, evidence, repositories: repositories, done: done, done_debs: debs,
                                                                on_start: on_start, on_done: on_done, verdicts: verdicts,
                                                                kept: kept.map(&:source))
                   else
                     build = lambda do |one|
                       files = build_one(plan, one, target, repositories, dir, backend, local.synchronize { debs.dup },
                                         verdicts)
                       local.synchronize { debs.concat(files.grep(/\.u?deb\z/)) }
                       files
                     end
                     run_local(plan, done, cutoff, on_start, on_done, build)
                   end
        results.write(backend: backend.name) if outcomes.empty?
        # a kept package built after all counts as built (or failed)
        TargetReport.new(target: target, dir: dir, results: results.within(plan.entries.map(&:source)),
                         outcomes: outcomes.map { |outcome| revoked.fetch(outcome.entry.source, outcome) }, reused: done.size, prepared: prepared)
      end

      # What the run does as each build ends: records it (and the kept
      # builds built after all before it, into +revoked+), writes the
      # results, tells the listener.
      def recorder(results, dir, digests, verdicts, cutoff, revoked, backend)
        lambda do |outcome|
          [*cutoff.drain, outcome].each do |each|
            revoked[each.entry.source] = each unless each.equal?(outcome)
            record(results, dir, each, digests[each.entry.source], verdicts)
          end
          results.write(backend: backend.name)
          @listener&.finished(outcome)
        end
      end

      # The early cutoff's evidence of the run's jobs (Slurm::JobEvidence),
      # the builds they may replace kept first: all but those +built+ by
      # an earlier run (a keep of an earlier run may be built after all).
      def job_evidence(plan, target, backend, results, built)
        dumps = ->(source, files, folder, log) { abi_dumps(source, files, folder, log) }
        Slurm::JobEvidence.new(Slurm::Run.new(plan, target, backend.name), dumps).tap do |evidence|
          evidence.keep(plan.entries.reject { |entry| built.include?(entry.source) }.map { |entry| results[entry.source] })
        end
      end

      # The Engine over the plan: a candidate's job waits, held, for its
      # decision (docs/scale-out.md).
      def run_slurm(plan, target, backend, evidence, **run)
        Slurm::Engine.new(cluster: Slurm::Cluster.new, settings: @slurm_settings, backend: backend, notices: @notices)
                     .run(plan: plan, target: target, keep_going: @keep_going, rebuild: @rebuild,
                          take: evidence.take(run[:verdicts]), **run)
                     .tap { evidence.drop }
      end

      # The entries an earlier run built and kept, reused by this one:
      # [built, kept]. A package built by another backend (a host build
      # after sbuild ones) is not what this run would build: built again.
      # A keep counts only while the cutoff is not refused and nothing of
      # its closure is built in this run: a keep was decided on its
      # closure's builds, and the same .dsc can name a version that was
      # only planned then (the kept one's) and is built now.
      def earlier(results, plan, digests, backend, refused)
        return [[], []] if @rebuild || results.backend != backend.name

        same = ->(check, entry) { results.public_send(check, entry.source, entry.version, digests[entry.source]) }
        built = plan.entries.select { |entry| same.call(:built?, entry) }
        done = built.to_h { |entry| [entry.source, true] }
        by_source = plan.entries.to_h { |entry| [entry.source, entry] }
        kept = plan.entries.select do |entry| # dependencies first
          !refused && same.call(:kept?, entry) && BuildPlan.closure(by_source, entry.source).all? { |need| done[need] } &&
            (done[entry.source] = true)
        end
        [built, kept]
      end

      # The Scheduler over the plan: a candidate the early cutoff keeps is
      # not built; a kept one a build needs is built first (EarlyCutoff).
      def run_local(plan, done, cutoff, on_start, on_done, build)
        Scheduler.new(plan.entries, jobs: @jobs, keep_going: @keep_going, done: done)
                 .run(on_start: on_start, on_done: on_done) do |entry|
          next Scheduler::Done.new(status: :kept, value: []) if cutoff.keep?(entry)

          cutoff.build_kept_for(entry, &build)
          build.call(entry)
        end
      end

      # The SHA256 of each planned .dsc: a record counts only for the exact
      # source package it was built from (nil when the .dsc is missing: the
      # build says so).
      def dsc_digests(plan)
        plan.entries.to_h do |entry|
          path = plan.dsc_path(entry)
          [entry.source, File.file?(path) ? Digest::SHA256.file(path).hexdigest : nil]
        end
      end

      # Builds +entry+ into a staging folder that replaces its previous
      # results only on success (StagedResults); +debs+: the .debs built so
      # far in this run; +verdicts+: Abi::InterfaceVerdicts (or NoVerdicts), which compares the
      # new files with the ones they replace before they do. Returns the
      # new files at their final paths.
      def build_one(plan, entry, target, repositories, dir, backend, debs, verdicts)
        staged = StagedResults.new(dir, entry.source)
        request = request_for(plan, entry, target, repositories, debs, dir, staged.prepare)
        files = backend.build(request)
        files += abi_dumps(request.source, files, request.output_dir, request.log)
        verdicts.decide(entry, files)
        staged.settle(files)
      end

      # +output_dir+: where the build puts its files (StagedResults#staging).
      def request_for(plan, entry, target, repositories, debs, dir, output_dir)
        log = UnlinkedPath.check(dir, OutputTree.log_name(entry.source))
        File.write(log, "")
        Request.new(source: entry.source, version: entry.version, dsc: File.expand_path(plan.dsc_path(entry)),
                    target: target, repositories: repositories, local_debs: debs, output_dir: output_dir, log: log)
      end

      # Why the early cutoff keeps nothing in this run, or nil: the
      # spec's early_cutoff, --rebuild-dependents.
      def refusal
        return "--rebuild-dependents: every candidate is built" if @rebuild_dependents

        setting = @effective.early_cutoff
        setting.enabled ? nil : "the early cutoff is off for #{@effective.release}: #{setting.reason}"
      end

      # +verdicts+: the run's verdicts (Abi::InterfaceVerdicts or NoVerdicts).
      def record(results, dir, outcome, dsc_sha256, verdicts)
        entry = outcome.entry
        started = !%i[skipped kept].include?(outcome.status)
        decided = Scheduler::SUCCESSES.include?(outcome.status)
        files = outcome.status == :built ? outcome.value.map { |file| BuildResults::Produced.of(dir, relative(dir, file)) } : []
        cutoff = decided ? verdicts.cutoff(entry.source) || verdicts.keep(entry) : nil
        files = kept_files(results[entry.source], cutoff) if outcome.status == :kept
        results.record(BuildResults::Record.new(
                         source: entry.source, package: entry.package, version: entry.version, dsc_sha256: dsc_sha256,
                         status: outcome.status.to_s,
                         duration: started ? outcome.duration : nil, log: started ? OutputTree.log_name(entry.source) : nil,
                         reason: outcome.reason&.gsub("#{dir}/", ""), files: files.freeze,
                         interface: outcome.status == :built ? verdicts[entry.source] : nil, cutoff: cutoff
                       ))
      end

      # The files of the build a keep keeps, as the record it replaces
      # lists them when that build is the one kept (else none): the next
      # build of the package is compared with them (docs/abi.md).
      def kept_files(previous, cutoff)
        previous && (previous.built? || previous.kept?) && previous.files_version == cutoff.keeps ? previous.files : []
      end

      # The ABI dumps of the libraries the build's .debs ship, into +dir+
      # (docs/abi.md); recorded with the produced files.
      def abi_dumps(source, files, dir, log)
        run = ->(command, log:) { @tool.run(source, command, log: log) }
        AbiDumper.new(run).dump(files.grep(/\.deb\z/), dir, log: log).map(&:path)
      end

      def debs_of(dir, record)
        record.files.map { |file| File.join(dir, file.name) }.grep(/\.u?deb\z/)
      end

      def relative(dir, file)
        file.delete_prefix("#{dir}/")
      end
    end
  end
end
