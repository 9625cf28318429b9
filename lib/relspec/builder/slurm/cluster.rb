# frozen_string_literal: true

require "json"
require "open3"
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

        def cancel(ids)
          run("scancel", *ids.map(&:to_s)) unless ids.empty?
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

        def capture(*command)
          Open3.capture2e(@env, *command)
        rescue SystemCallError => e
          raise BuildError, "cannot run #{command.first}: #{e.message.sub(/ - .*\z/, '')} " \
                            "(the Slurm client tools: apt-get install slurm-client)"
        end
      end
    end
  end
end
