# frozen_string_literal: true

require_relative "../../output_tree"
require_relative "../../atomic_file"
require_relative "../../error"
require_relative "../request"
require_relative "../staged_results"
require_relative "job_script"
require_relative "file_pattern"

module Relspec
  module Builder
    module Slurm
      # Submits the jobs of one Run: a chroot-prepare job on a node of the
      # target's architecture, then one job per pending source package
      # depending (afterok) on it and on the jobs of its build-dependencies
      # built in this run, each written as a JobScript. Everything is
      # submitted held, in plan (topological) order, and released at once;
      # the run's jobs still in the queue are adopted, not submitted again.
      class Submission
        # What was submitted or adopted so far, also when submitting
        # stopped half-way (what an interrupted run cancels): the ids
        # submitted, the chroot job's id, and {job id => entry} of the
        # builds, in plan order.
        attr_reader :submitted, :prepare_id, :tracked

        def initialize(cluster:, settings:, backend:, run:, plan:, target:)
          @cluster = cluster
          @settings = settings
          @backend = backend
          @run = run
          @plan = plan
          @target = target
          @submitted = []
          @prepare_id = nil
          @tracked = {}
        end

        # +pending+: the BuildPlan entries to build; +live+: the run's jobs
        # in the queue (Run#live_jobs); +hold+: true for a source whose job
        # waits, held, for the early cutoff's decision (HeldCandidates):
        # it depends on the chroot job alone until then (#depend sets the
        # rest), so that a job the cutoff cancels is no job's dependency.
        # Returns the ids left held.
        def call(pending, live, repositories, done_debs, hold: ->(_source) { false })
          @repositories = repositories
          @done_debs = done_debs
          @in_run = pending.to_h { |entry| [entry.source, entry] }
          @ids = {}
          held = live.reject { |source, _| hold.call(source) }.values.select(&:held?).map(&:id)
          @prepare_id = live["chroot"]&.id || submit_prepare
          held << @prepare_id unless live["chroot"]
          kept_held = []
          pending.each do |entry|
            adopted = live[entry.source]
            waits = hold.call(entry.source)
            @ids[entry.source] = adopted&.id || submit_build(entry, waits ? [@prepare_id] : nil)
            if adopted
              kept_held << adopted.id if waits && adopted.held?
            else
              (waits ? kept_held : held) << @ids[entry.source]
            end
            @tracked[@ids[entry.source]] = entry
          end
          @cluster.release(held)
          kept_held
        end

        # Releases the job +id+ of +entry+, a candidate decided rebuild,
        # with new jobs for the kept packages it names (+revoked+: entries,
        # built after all, first). +held+: false for a job an earlier
        # relspec of the run released (the kept ones alone are released);
        # +prepare_live+: the chroot job has not ended.
        def release_decided(id, entry, revoked, prepare_live:, held:)
          live = -> { [*(prepare_live ? [@prepare_id] : []), *@tracked.keys] }
          again = revoked.map { |kept| resubmit(kept, live.call) }
          return @cluster.release(again) unless held

          if again.empty?
            # afterok on the jobs of its closure not ended yet
            @cluster.depend(id, [@prepare_id, *closure_ids(entry)] & live.call)
          else
            # Slurm keeps the script a job was submitted with: the held one
            # (no job's dependency) gives way to one naming the new builds
            @tracked.delete(id)
            @cluster.cancel([id])
            id = resubmit(entry, live.call)
          end
          @cluster.release([*again, id])
        end

        # Submits +entry+'s build again, held (a package the early cutoff
        # kept is built after all, or one that names it), now built in the
        # run (its folder given to the builds that need it), after the jobs
        # of its closure that are among +live+ (ids of this relspec's jobs
        # not yet ended, the chroot job's among them while it runs): job
        # ids that may have left Slurm's memory are never a dependency.
        def resubmit(entry, live)
          @in_run[entry.source] = entry
          id = submit_build(entry, [@prepare_id, *closure_ids(entry)].select { |one| live.include?(one) })
          @tracked[@ids[entry.source] = id] = entry
          id
        end

        # The ids of the jobs of +entry+'s closure in this run (after a
        # resubmission, the new ones).
        def closure_ids(entry)
          ancestors(entry).filter_map { |source| @ids[source] }
        end

        private

        def submit_prepare
          path = File.join(@run.jobs_dir, "chroot.sh")
          AtomicFile.write(path, JobScript.render(title: "relspec: prepare the #{@target} chroot (run #{@run.id})",
                                                  steps: @backend.prepare_steps(@target),
                                                  work: @run.work_dir("chroot"), result: @run.result_path("chroot")))
          submit(path, "chroot", @run.prepare_log, [])
        end

        # +deps+: the jobs it waits for (default: the chroot job and those
        # of its closure).
        def submit_build(entry, deps = nil)
          ancestors = ancestors(entry)
          dir = @run.dir
          staged = StagedResults.new(dir, entry.source)
          request = Request.new(source: entry.source, version: entry.version, dsc: File.expand_path(@plan.dsc_path(entry)),
                                target: @target, repositories: @repositories,
                                local_debs: @done_debs + ancestors.map { |source| File.join(dir, OutputTree.results_name(source)) },
                                output_dir: staged.final, log: @run.log_path(entry.source))
          work = @run.work_dir(entry.source)
          path = File.join(@run.jobs_dir, "#{entry.source}.sh")
          script = JobScript.render(title: "relspec: build #{entry.source} #{entry.version} for #{@plan.release} " \
                                           "#{@target} (run #{@run.id})",
                                    steps: @backend.job_steps(request, work), work: work,
                                    result: @run.result_path(entry.source), output_dir: request.output_dir,
                                    staging: staged.staging,
                                    prefix: OutputTree.results_name(entry.source))
          AtomicFile.write(path, script)
          # afterok on every build of the run the job's backend installs
          # (the closure), not only the direct build-dependencies
          submit(path, entry.source, request.log, deps || [@prepare_id, *ancestors.filter_map { |source| @ids[source] }])
        end

        # The build-dependencies of +entry+ built in this run, also
        # indirect ones (sbuild installs them all from the folders given).
        def ancestors(entry, seen = {})
          entry.build_depends.each do |dep|
            next if seen[dep] || !@in_run[dep]

            seen[dep] = true
            ancestors(@in_run[dep], seen)
          end
          seen.keys.sort
        end

        def submit(path, source, log, deps)
          feature = @settings.feature(@target.arch)
          options = ["--job-name=#{@run.job_name(source)}", "--output=#{FilePattern.escape(log)}", "--open-mode=truncate",
                     "--chdir=#{@run.jobs_dir}", "--kill-on-invalid-dep=yes", *@settings.sbatch_options,
                     *(feature ? ["--constraint=#{feature}"] : []),
                     *(deps.empty? ? [] : ["--dependency=afterok:#{deps.join(':')}"])]
          @cluster.submit(path, options).tap { |id| @submitted << id }
        rescue BuildError => e
          raise unless e.message.include?("Invalid feature")

          raise BuildError, "#{@target}: no node of the Slurm cluster has the feature #{feature} that builds for " \
                            "#{@target.arch} need (set it on the nodes that build #{@target.arch}, natively or by " \
                            "emulation, or name their feature with --slurm features.#{@target.arch}=NAME; " \
                            "docs/scale-out.md)"
        end
      end
    end
  end
end
