# frozen_string_literal: true

module Relspec
  module Builder
    module Slurm
      # What failed in one Slurm run of a target, and the words of each
      # outcome it causes: a failed package or chroot job, the packages
      # skipped because of it (each traced back to the failure it comes
      # from), and those not started because the run stopped.
      class Failures
        CHROOT = "chroot"

        # +run+: the Run; +target+: its Target.
        def initialize(run, target)
          @run = run
          @target = target
          @failed = {} # source => the failed source (or chroot job) it goes back to
        end

        # The chroot job ended other than COMPLETED (+job+: Cluster::Job).
        def chroot(job)
          @failed[CHROOT] ||= "the #{@target} chroot job failed (#{job.state}, see #{@run.prepare_log})"
        end

        def chroot_failed?
          @failed.key?(CHROOT)
        end

        # +entry+ failed itself.
        def failed(entry)
          @failed[entry.source] = entry.source
        end

        # +entry+ is skipped: it goes back to +root+ (default: its own).
        def skipped(entry, root = root(entry))
          @failed[entry.source] = root || entry.source
        end

        # The failure +entry+ goes back to (a source, or the chroot job's
        # words), or nil.
        def root(entry)
          return @failed[CHROOT] if chroot_failed?

          dep = entry.build_depends.find { |source| @failed[source] }
          dep && @failed[dep]
        end

        def skip_reason(root)
          root == @failed[CHROOT] ? root : "build-dependency #{root} failed"
        end

        def not_started
          "not started: the run stopped after #{@failed.select { |source, root| source == root }.keys.sort.join(', ')} " \
            "failed (--keep-going builds the rest)"
        end

        # Why the job +id+ (+job+: as Slurm last showed it, or nil) of
        # +entry+ failed; +result+: its result file, or nil.
        def reason(id, entry, job, result)
          log = @run.log_path(entry.source)
          return "#{entry.source}: Slurm job #{id} left the queue without a result, see #{log}" unless job

          exit = result ? result.exit_status : job.exit_code
          "#{entry.source}: Slurm job #{id} #{job.state}#{" (exit status #{exit})" if exit}, see #{log}"
        end
      end
    end
  end
end
