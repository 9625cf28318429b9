# frozen_string_literal: true

require "fileutils"
require_relative "../../error"
require_relative "../scheduler"
require_relative "failures"
require_relative "held_candidates"
require_relative "job_result"
require_relative "run"
require_relative "submission"

module Relspec
  module Builder
    module Slurm
      # Builds one target's plan on a Slurm cluster: relspec keeps the
      # graph and the backend's command lines, Slurm places and runs the
      # jobs (Submission: a chroot-prepare job, then one job per source
      # package, held and released at once), and the Engine follows them
      # to their outcomes.
      #
      # The Run's id is a digest of the target folder, the backend and
      # plan.yml: running again on the same plan adopts the run's jobs still
      # in the queue and submits only what is missing. Job ids of earlier
      # runs are never used in a dependency: Slurm treats an id it has
      # forgotten as satisfied.
      #
      # Outcomes are Scheduler::Outcome, handed to +on_done+ as the local
      # scheduler does, so build-results.yml is written the same way.
      #
      # The early cutoff (HeldCandidates): a candidate's job stays held
      # until every package of its closure has its outcome; then the run's
      # verdicts decide it, and its job is cancelled (kept) or released.
      class Engine
        # States after which a job does not run again.
        CANCELLED = "CANCELLED"
        COMPLETED = "COMPLETED"
        # How long an interrupted run waits for its cancelled jobs to end.
        CANCEL_WAIT = 15

        def initialize(cluster:, settings:, backend:, notices: nil)
          @cluster = cluster
          @settings = settings
          @backend = backend
          @notices = notices
        end

        # +plan+: BuildPlan; +done+: sources built or kept before (not run
        # again); +done_debs+: their .debs; +repositories+: as for the local
        # builds; +rebuild+: the result files of an earlier relspec of this
        # run are not taken either. +verdicts+: the early cutoff's
        # (Abi::InterfaceVerdicts, or Builder::NoVerdicts); +kept+: the
        # sources of +done+ an earlier run kept; +take+: called with (entry,
        # paths) for a job's verified files, returns the build's files (with
        # the ABI dumps made here; the verdicts decided).
        def run(plan:, target:, repositories:, done:, done_debs:, keep_going:, verdicts:, rebuild: false, on_start: nil,
                on_done: nil, kept: [], take: ->(_entry, paths) { paths })
          @plan = plan
          @target = target
          @dir = plan.dir
          @run = Run.new(plan, target, @backend.name)
          FileUtils.mkdir_p(@run.jobs_dir)
          @on_start = on_start
          @on_done = on_done
          @outcomes = []
          @failures = Failures.new(@run, target)
          @stopped = false
          @keep_going = keep_going
          @take = take
          @order = plan.entries.each_with_index.to_h { |entry, index| [entry.source, index] }
          @settled = done.to_h { |source| [source, true] } # built or kept
          @tracked = {} # job id => entry
          @submission = @prepare_id = nil # this run's, not an earlier target's
          live = @run.live_jobs(@cluster.queue)
          pending = start_cutoff(plan, done, live, verdicts, kept, rebuild)
          pending = settle_finished(pending, live) unless rebuild
          return @outcomes if pending.empty?

          submit_all(pending, live, repositories, done_debs)
          decide_ready
          poll
          @outcomes
        rescue Interrupt
          cancel_all
          raise
        end

        private

        # The entries to build or decide: those not done, and the keeps of
        # earlier runs a package built now names at their new version
        # (HeldCandidates#revoked_at_start).
        def start_cutoff(plan, done, live, verdicts, kept, rebuild)
          pending = plan.entries.reject { |entry| done.include?(entry.source) }
          released = pending.select do |entry|
            job = live[entry.source]
            job ? !job.held? : !rebuild && JobResult.read(@run.result_path(entry.source), @dir)&.built?
          end
          @cutoff = HeldCandidates.new(verdicts, plan.entries, pending: pending, kept: kept,
                                                               released: released.map(&:source))
          revoked = @cutoff.revoked_at_start
          revoked.each { |entry| @settled.delete(entry.source) }
          plan.entries.select { |entry| pending.include?(entry) || revoked.include?(entry) }
        end

        # Packages whose job (of an earlier relspec of this run) finished
        # and wrote a verified result: recorded built without a new job.
        def settle_finished(pending, live)
          pending.reject do |entry|
            next false if live[entry.source]

            result = JobResult.read(@run.result_path(entry.source), @dir)
            next false unless result&.built? && result.problem(entry.source, entry.version).nil?

            report(taken(entry, result))
            true
          rescue Relspec::Error
            false # its evidence cannot be made: built again
          end
        end

        # The outcome of +entry+'s verified job result: built, with its
        # evidence (+take+). A candidate an earlier relspec of the run let
        # build is decided first (HeldCandidates: built).
        def taken(entry, result)
          @cutoff.decide(entry) if @cutoff.undecided?(entry.source)
          Scheduler::Outcome.new(entry: entry, status: :built, value: @take.call(entry, result.paths),
                                 duration: result.duration)
        end

        # Decides every held candidate whose closure has its outcomes: a
        # kept one's job is cancelled (it never ran), a rebuilt one's
        # released, after the kept packages it names are submitted again.
        def decide_ready
          while (entry = @cutoff.ready(@settled.keys).find { |one| @tracked.value?(one) })
            id = @tracked.key(entry)
            decision = @cutoff.decide(entry)
            next keep(id, entry) if decision.keep

            decision.revoke.each { |kept| @settled.delete(kept.source) }
            @submission.release_decided(id, entry, decision.revoke, prepare_live: @prepare_live, held: @held.delete(id))
          end
        end

        def keep(id, entry)
          @tracked.delete(id) && @held.delete(id)
          cancel([id])
          report(Scheduler::Outcome.new(entry: entry, status: :kept, value: []))
        end

        # @tracked in plan order: a package settles after its closure in
        # one round (its record never names a build not recorded yet).
        def in_plan_order
          @tracked.sort_by { |id, entry| [@order[entry.source], id] }
        end

        def submit_all(pending, live, repositories, done_debs)
          @submission = Submission.new(cluster: @cluster, settings: @settings, backend: @backend, run: @run, plan: @plan,
                                       target: @target)
          @tracked = @submission.tracked
          # the ids of the jobs held for the early cutoff's decision
          @held = @submission.call(pending, live, repositories, done_debs, hold: @cutoff.method(:undecided?))
          @prepare_id = @submission.prepare_id
          @prepare_live = true
        rescue BuildError
          cancel_all # nothing of a refused run stays held in the queue
          raise
        end

        def poll
          started = {}
          until @tracked.empty?
            sleep @settings.poll_interval
            queue = @cluster.queue.to_h { |job| [job.id, job] }
            missing = @tracked.keys.reject { |id| queue[id] }
            @cluster.accounting(missing).each { |job| queue[job.id] = job }
            check_prepare(queue)
            in_plan_order.each do |id, entry|
              next unless @tracked.key?(id) # settled as a dependent of a failure in this round

              job = queue[id]
              if job&.live?
                @on_start&.call(entry) if job.state == "RUNNING" && !started[id] && (started[id] = true)
                next
              end
              settle(id, entry, job)
            end
            decide_ready
          end
        end

        # A failed chroot job fails the whole target: its builds are
        # cancelled by Slurm (afterok), recorded skipped naming it.
        def check_prepare(queue)
          job = queue[@prepare_id]
          @prepare_live &&= job&.live?
          return if @failures.chroot_failed? || job.nil? || job.live? || job.state == COMPLETED

          @failures.chroot(job)
        end

        def settle(id, entry, job)
          @tracked.delete(id)
          result = JobResult.read(@run.result_path(entry.source), @dir)
          state = job&.state
          if (state.nil? || state == COMPLETED) && result&.built?
            problem = result.problem(entry.source, entry.version)
            return fail(entry, "#{entry.source}: Slurm job #{id}: #{problem}", result&.duration) if problem

            begin
              return report(taken(entry, result))
            rescue Relspec::Error => e
              return fail(entry, "#{entry.source}: #{e.message}", result.duration)
            end
          end
          root = @failures.root(entry)
          return skip(entry, @failures.skip_reason(root)) if root
          return skip(entry, @failures.not_started) if state == CANCELLED && @stopped

          fail(entry, @failures.reason(id, entry, job, result), result&.duration)
        end

        def fail(entry, reason, duration)
          @failures.failed(entry)
          report(Scheduler::Outcome.new(entry: entry, status: :failed, reason: reason, duration: duration))
          skip_dependents
          stop unless @keep_going
        end

        def skip(entry, reason)
          @failures.skipped(entry)
          report(Scheduler::Outcome.new(entry: entry, status: :skipped, reason: reason))
        end

        # Reverse dependencies of a failure (transitively, in plan order):
        # cancelled now rather than when Slurm notices.
        def skip_dependents
          in_plan_order.each do |id, entry|
            root = @failures.root(entry)
            next unless root

            @tracked.delete(id)
            cancel([id])
            @failures.skipped(entry, root)
            report(Scheduler::Outcome.new(entry: entry, status: :skipped, reason: @failures.skip_reason(root)))
          end
        end

        # Without --keep-going nothing new starts after a failure: the jobs
        # still waiting are cancelled; running ones finish.
        def stop
          @stopped = true
          queue = @cluster.queue.to_h { |job| [job.id, job] }
          waiting = @tracked.keys.select { |id| queue[id]&.state == "PENDING" }
          cancel(waiting)
          waiting.each { |id| skip(@tracked.delete(id), @failures.not_started) }
        end

        # A kept package built after all has its second outcome.
        def report(outcome)
          @outcomes.reject! { |one| one.entry.source == outcome.entry.source }
          @outcomes << outcome
          @settled[outcome.entry.source] = true if Scheduler::SUCCESSES.include?(outcome.status)
          @on_done&.call(outcome)
        end

        def cancel(ids)
          @cluster.cancel(ids)
        rescue BuildError
          nil # a job that ended meanwhile cannot be cancelled: nothing to do
        end

        # "cancelled" is said when it is true: Cluster#cancel_and_wait
        # waits, bounded, for the jobs to end, and those still ending are named.
        def cancel_all
          ids = (Array(@submission&.submitted) + @tracked.keys + [@prepare_id || @submission&.prepare_id].compact).uniq.sort
          return if ids.empty?

          ending = begin
            @cluster.cancel_and_wait(ids, seconds: CANCEL_WAIT)
          rescue BuildError
            [] # a job that ended meanwhile cannot be cancelled: nothing to do
          end
          message = "relspec: cancelled the Slurm jobs of run #{@run.id}: #{ids.join(', ')}"
          message += " (still ending: #{ending.join(', ')}; squeue shows when they have)" unless ending.empty?
          @notices&.puts(message)
        end
      end
    end
  end
end
