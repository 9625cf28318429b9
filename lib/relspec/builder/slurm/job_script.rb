# frozen_string_literal: true

require_relative "../shell_line"

module Relspec
  module Builder
    module Slurm
      # The shell script of one Slurm job: runs a backend's steps in a
      # fresh folder on the node, moves what the build produced to a
      # staging folder beside the package's results folder (on the shared
      # filesystem), which takes the results folder's place only when the
      # build succeeded (as StagedResults does for local builds: a failed
      # or cancelled rebuild leaves the previous build's files where its
      # record says they are; the swap is the job's own because the jobs
      # that depend on it start as soon as it ends, before relspec looks),
      # and writes the job's result file last (JobResult reads it): status,
      # exit status, duration and every file with its SHA256 and size. The
      # script exits with the build's status, so Slurm's afterok sees a
      # failure.
      module JobScript
        module_function

        # +title+: a comment line; +steps+: shell lines run in +work+;
        # +output_dir+: <target folder>/results/<source> (nil for a job
        # that produces nothing); +staging+: where the build's files wait
        # (StagedResults#staging); +prefix+: the files' names in the result
        # are relative to the target folder, e.g. "results/<source>".
        def render(title:, steps:, work:, result:, output_dir: nil, staging: nil, prefix: nil)
          <<~SH
            #!/bin/sh
            # #{title}
            # Written by `relspec build --engine slurm`; the result file is written last.
            work=#{ShellLine.quote(work)}
            result=#{ShellLine.quote(result)}
            out=#{ShellLine.quote(output_dir.to_s)}
            stage=#{ShellLine.quote(staging.to_s)}
            started=$(date +%s.%N)
            rm -rf "$work" "$result"
            mkdir -p "$work"
            trap 'rm -rf "$work"' EXIT
            # scancel sends TERM: leave through the EXIT trap
            trap 'exit 143' TERM INT
            if [ -n "$out" ]; then rm -rf "$stage" && mkdir -p "$stage"; fi
            steps() {
              set -e
              cd "$work"
            #{steps.map { |step| "  echo #{ShellLine.quote("$ #{step}")}\n  #{step}" }.join("\n")}
            }
            ( steps ) 2>&1
            status=$?
            if [ "$status" -eq 0 ] && [ -n "$out" ]; then
              for file in "$work"/*.deb "$work"/*.udeb "$work"/*.buildinfo "$work"/*.changes; do
                [ ! -f "$file" ] || mv "$file" "$stage"/ || status=$?
              done
              if [ "$status" -eq 0 ]; then rm -rf "$out" && mv "$stage" "$out" || status=$?; fi
            fi
            {
              echo "relspec_job_result 1"
              if [ "$status" -eq 0 ]; then echo "status built"; else echo "status failed"; fi
              echo "exit $status"
              echo "duration $(echo "$started $(date +%s.%N)" | awk '{ printf "%.1f", $2 - $1 }')"
              if [ "$status" -eq 0 ] && [ -n "$out" ]; then
                for file in "$out"/*; do
                  [ ! -f "$file" ] || echo "file $(sha256sum < "$file" | cut -d' ' -f1) $(stat -c %s "$file") #{prefix}/$(basename "$file")"
                done
              fi
            } > "$result.partial" && mv "$result.partial" "$result"
            exit "$status"
          SH
        end
      end
    end
  end
end
