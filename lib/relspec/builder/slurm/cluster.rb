# frozen_string_literal: true

require "json"
require_relative "../../error"
require_relative "../tool"

module Relspec
  module Builder
    module Slurm
      # The Slurm commands relspec runs (sbatch, scontrol, squeue, sacct,
      # scancel), each one process through the cluster's own client tools:
      # relspec talks to Slurm as a person at a login node would.
      class Cluster
        # A job as squeue or sacct shows it: +state+ e.g. "PENDING",
        # "COMPLETED", "FAILED"; +reason+: Slurm's state reason;
        # +exit_code+: the job script's exit status.
        Job = Struct.new(:id, :name, :state, :reason, :exit_code, keyword_init: true) do
          def held?
            state == "PENDING" && reason.to_s.start_with?("JobHeld")
          end

          def live?
            %w[PENDING RUNNING CONFIGURING COMPLETING SUSPENDED REQUEUED RESIZING].include?(state)
          end
        end

        def initialize(env: {})
          @env = Tool::OUTSIDE_BUNDLE.merge(env)
        end

        # Submits +script+ held; returns the job id. +options+: sbatch's
        # options. A refusal (an unknown partition, a feature no node has)
        # raises BuildError with Slurm's own words.
        def submit(script, options)
          output = run("sbatch", "--parsable", "--hold", *options, script)
          Integer(output.strip.split(";").first)
        rescue ArgumentError
          raise BuildError, "sbatch printed no job id for #{script}: #{output.strip}"
        end

        def release(ids)
          run("scontrol", "release", ids.join(",")) unless ids.empty?
        end

        # Makes the pending job +id+ wait for (afterok) the jobs +ids+
        # alone (none: for nothing).
        def depend(id, ids)
          run("scontrol", "update", "JobId=#{id}", "Dependency=#{"afterok:#{ids.join(':')}" unless ids.empty?}")
        end

        def cancel(ids)
          run("scancel", *ids.map(&:to_s)) unless ids.empty?
        end

        # scancel only asks: a running job passes through COMPLETING while
        # its node kills the script (about a second). Cancels +ids+ and
        # waits up to +seconds+ for them to leave the queue's live states;
        # returns the ids still live then.
        def cancel_and_wait(ids, seconds:, poll: 0.2)
          cancel(ids)
          deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + seconds
          loop do
            live = live_among(ids)
            return live if live.empty? || Process.clock_gettime(Process::CLOCK_MONOTONIC) >= deadline

            sleep poll
          end
        end

        # Every job squeue knows (also finished ones, until MinJobAge).
        def queue
          jobs(run("squeue", "--json"))
        end

        # The jobs +ids+ as accounting recorded them; [] when the cluster
        # has no accounting (squeue alone then tells the states).
        def accounting(ids)
          return [] if ids.empty?

          output, status = capture("sacct", "--json", "--jobs=#{ids.join(',')}")
          status.success? ? jobs(output) : []
        end

        private

        def live_among(ids)
          states = queue.to_h { |job| [job.id, job] }
          ids.select { |id| states[id]&.live? }
        rescue BuildError
          [] # squeue itself failed: nothing more can be known, and the cancel was sent
        end

        def jobs(output)
          data = JSON.parse(output)
          Array(data["jobs"]).map do |job|
            state = job["job_state"] || job.dig("state", "current")
            Job.new(id: job["job_id"], name: job["name"], state: Array(state).first.to_s,
                    reason: job["state_reason"] || job.dig("state", "reason"), exit_code: exit_code(job["exit_code"]))
          end
        rescue JSON::ParserError => e
          raise BuildError, "cannot read what Slurm printed (#{e.message[0, 80]}): is this Slurm 22.05 or newer?"
        end

        # squeue gives the wait status (exit status << 8); sacct a hash.
        def exit_code(value)
          return value["return_code"] if value.is_a?(Hash)

          value.is_a?(Integer) ? value >> 8 : nil
        end

        def run(*command)
          output, status = capture(*command)
          return output if status.success?

          raise BuildError, "#{command.first} refused: #{output.strip.lines.last&.strip || "exit status #{status.exitstatus}"}"
        end

        # IO.popen, not Open3: an interrupt while a command runs must not
        # leave a reader thread to die noisily on a closed stream.
        def capture(*command)
          output = IO.popen(@env, command, err: %i[child out], in: File::NULL, &:read)
          [output, Process.last_status]
        rescue SystemCallError => e
          raise BuildError, "cannot run #{command.first}: #{e.message.sub(/ - .*\z/, '')} " \
                            "(the Slurm client tools: apt-get install slurm-client)"
        end
      end
    end
  end
end
