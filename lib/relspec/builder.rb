# frozen_string_literal: true

require "fileutils"
require_relative "release_spec"
require_relative "error"
require_relative "builder/build_plan"
require_relative "builder/results"
require_relative "builder/request"
require_relative "builder/repositories"
require_relative "builder/scheduler"
require_relative "builder/tool"
require_relative "builder/host_backend"
require_relative "builder/sbuild_backend"
require_relative "builder/slurm/cluster"
require_relative "builder/slurm/engine"
require_relative "builder/slurm/settings"

module Relspec
  # `relspec build`: builds the source packages `relspec compile` wrote,
  # per target in the order of its plan.yml, with one backend, and records
  # every package's outcome in <target folder>/build-results.yml (Results).
  # Built files go to <target folder>/results/<source>/, logs to
  # <target folder>/logs/<source>.log. docs/build.md describes it.
  module Builder
    BACKENDS = %w[sbuild host].freeze
    ENGINES = %w[local slurm].freeze

    # Per target: +reused+ counts packages an earlier run built (files checked).
    TargetReport = Struct.new(:target, :dir, :results, :outcomes, :reused, :prepared, keyword_init: true) do
      def failed?
        outcomes.any? { |outcome| outcome.status != :built }
      end
    end

    # +targets+: ["codename/arch"] to build (default: every target of the
    # spec); +listener+: receives start(target, total, done), building(entry),
    # finished(outcome) for progress output. +engine+: "local" (the
    # Scheduler, --jobs at once) or "slurm" (Slurm::Engine with
    # +slurm_settings+); +notices+: where the Slurm engine says what it
    # cancelled.
    def self.run(path, out:, backend: "sbuild", jobs: 1, targets: nil, keep_going: false, rebuild: false,
                 prepare_only: false, listener: nil, engine: "local", slurm_settings: nil, notices: nil)
      Run.new(path, out: out, backend: backend, jobs: jobs, targets: targets, keep_going: keep_going,
                    rebuild: rebuild, prepare_only: prepare_only, listener: listener,
                    engine: engine, slurm_settings: slurm_settings, notices: notices).call
    end

    # One `relspec build` run.
    class Run
      def initialize(path, out:, backend:, jobs:, targets:, keep_going:, rebuild:, prepare_only:, listener:,
                     engine: "local", slurm_settings: nil, notices: nil)
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
      end

      def call
        resolution = ReleaseSpec.resolve(@path)
        @effective = resolution.effective
        backend = make_backend
        selected_targets.map do |target|
          dir = File.expand_path(File.join(@out, @effective.release, "#{target.codename}-#{target.arch}"))
          plan = BuildPlan.read(dir)
          FileUtils.mkdir_p(File.join(dir, "logs"))
          # on a cluster the chroot-prepare job of the target makes it, on a node
          prepared = slurm? && !@prepare_only ? false : backend.prepare(target, log: File.join(dir, "logs", "prepare.log"))
          next TargetReport.new(target: target, dir: dir, outcomes: [], reused: 0, prepared: prepared) if @prepare_only

          build_target(target, dir, plan, backend, Repositories.of(resolution, target.codename), prepared)
        end
      rescue Interrupt
        @tool.stop_all
        raise
      end

      private

      def make_backend
        case @backend_name
        when "host" then HostBackend.new(@tool)
        when "sbuild" then SbuildBackend.new(@tool, @effective.distributions, chroot_cache: shared_chroots)
        else raise BuildError, "unknown backend #{@backend_name.inspect} (known: #{BACKENDS.join(', ')})"
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

      def selected_targets
        all = @effective.targets.flat_map { |codename, arches| Array(arches).map { |arch| Target.new(codename, arch) } }
        return all if @only.nil? || @only.empty?

        @only.uniq.map do |name|
          all.find { |target| target.to_s == name } or
            raise InvalidOption, "#{@effective.release} has no target #{name} (targets: #{all.join(', ')})"
        end
      end

      def build_target(target, dir, plan, backend, repositories, prepared)
        results = Results.read(dir)
        current = plan.entries.to_h { |entry| [entry.source, true] }
        results.records.select! { |source, _| current[source] } # what compile no longer plans is not a result
        # A package built by another backend (a host build after sbuild ones)
        # is not what this run would build: built again.
        reuse = !@rebuild && results.backend == backend.name
        done = reuse ? plan.entries.select { |entry| results.built?(entry.source, entry.version) }.map(&:source) : []
        @listener&.start(target, plan.entries.size, done.size)
        local = Mutex.new
        debs = done.flat_map { |source| debs_of(dir, results[source]) }
        on_start = ->(entry) { @listener&.building(entry) }
        on_done = lambda do |outcome|
          record(results, dir, outcome)
          results.write(release: @effective.release, target: target.to_s, backend: backend.name)
          @listener&.finished(outcome)
        end
        outcomes = if slurm?
                     Slurm::Engine.new(cluster: Slurm::Cluster.new, settings: @slurm_settings, backend: backend,
                                       notices: @notices)
                                  .run(plan: plan, target: target, repositories: repositories, done: done,
                                       done_debs: debs, keep_going: @keep_going, rebuild: @rebuild,
                                       on_start: on_start, on_done: on_done)
                   else
                     Scheduler.new(plan.entries, jobs: @jobs, keep_going: @keep_going, done: done)
                              .run(on_start: on_start, on_done: on_done) do |entry|
                       request = request_for(plan, entry, target, repositories, local.synchronize { debs.dup }, dir)
                       files = backend.build(request)
                       local.synchronize { debs.concat(files.grep(/\.u?deb\z/)) }
                       files
                     end
                   end
        results.write(release: @effective.release, target: target.to_s, backend: backend.name) if outcomes.empty?
        TargetReport.new(target: target, dir: dir, results: results, outcomes: outcomes, reused: done.size,
                         prepared: prepared)
      end

      def request_for(plan, entry, target, repositories, debs, dir)
        output_dir = File.join(dir, "results", entry.source)
        log = File.join(dir, "logs", "#{entry.source}.log")
        FileUtils.rm_rf(output_dir)
        File.write(log, "")
        Request.new(source: entry.source, version: entry.version, dsc: File.expand_path(plan.dsc_path(entry)),
                    target: target, repositories: repositories, local_debs: debs, output_dir: output_dir, log: log)
      end

      def record(results, dir, outcome)
        entry = outcome.entry
        started = outcome.status != :skipped
        files = outcome.status == :built ? outcome.value.map { |file| Results.file_entry(dir, relative(dir, file)) } : nil
        results.record(entry.source, Results::Record.new(
                                       package: entry.package, version: entry.version, status: outcome.status.to_s,
                                       duration: started ? outcome.duration : nil,
                                       log: started ? "logs/#{entry.source}.log" : nil,
                                       reason: outcome.reason&.gsub("#{dir}/", ""),
                                       files: files
                                     ))
      end

      def debs_of(dir, record)
        record.files.map { |file| File.join(dir, file["name"]) }.grep(/\.u?deb\z/)
      end

      def relative(dir, file)
        file.delete_prefix("#{dir}/")
      end
    end
  end
end
