# frozen_string_literal: true

require "digest"
require_relative "../build_plan"

module Relspec
  module Builder
    module Slurm
      # One Slurm run of a target's plan: its id, a digest of the target
      # folder, the backend and plan.yml (running again on the same plan is
      # the same run), the names of its jobs, and the files each job writes.
      class Run
        attr_reader :id, :dir, :jobs_dir

        # +plan+: BuildPlan; +backend_name+: the backend's name.
        def initialize(plan, target, backend_name)
          @plan = plan
          @target = target
          @dir = plan.dir
          @id = Digest::SHA256.hexdigest([@dir, backend_name, File.read(File.join(@dir, BuildPlan::FILE))].join("\0"))[0, 12]
          @jobs_dir = File.join(@dir, "slurm", @id)
        end

        def job_name(source)
          "#{prefix}#{source}#{suffix}"
        end

        # The run's jobs still queued or running in +queue+ (an earlier
        # relspec of this run was killed): source (or "chroot") => job.
        def live_jobs(queue)
          queue.select { |job| job.live? && job.name.to_s.end_with?(suffix) && job.name.start_with?(prefix) }
               .sort_by(&:id).to_h { |job| [job.name.delete_prefix(prefix).delete_suffix(suffix), job] }
        end

        def result_path(source) = File.join(@jobs_dir, "#{source}.result")

        def log_path(source) = File.join(@dir, "logs", "#{source}.log")

        def prepare_log = File.join(@dir, "logs", "prepare.log")

        # On the node, outside the shared filesystem.
        def work_dir(source)
          File.join("/tmp", "relspec-slurm-#{@id}-#{source}")
        end

        private

        def prefix = "#{@plan.release}/#{@target.dir_name}/"

        def suffix = "@#{@id}"
      end
    end
  end
end
