# frozen_string_literal: true

require "digest"

module Relspec
  module Builder
    module Slurm
      # The result file a job wrote last (JobScript), checked against the
      # files on the shared filesystem: a built result counts only when
      # every file it lists is there with the size and SHA256 the node saw.
      class JobResult
        attr_reader :status, :exit_status, :duration, :files

        # nil when the job wrote no (complete) result file.
        def self.read(path, dir)
          return nil unless File.file?(path)

          lines = File.readlines(path, chomp: true)
          return nil unless lines.first == "relspec_job_result 1"

          fields = lines.drop(1).map { |line| line.split(" ", 2) }
          files = fields.select { |key, _| key == "file" }.map do |_, value|
            sha256, size, name = value.split(" ", 3)
            { "name" => name, "sha256" => sha256, "size" => Integer(size, 10) }
          end
          values = fields.reject { |key, _| key == "file" }.to_h
          new(values["status"], Integer(values.fetch("exit", "1"), 10), Float(values.fetch("duration", "0")), files, dir)
        rescue ArgumentError
          nil
        end

        def initialize(status, exit_status, duration, files, dir)
          @status = status
          @exit_status = exit_status
          @duration = duration
          @files = files
          @dir = dir
        end

        def built?
          @status == "built"
        end

        # The first listed file that is missing or has other bytes than
        # the node recorded; nil when all match.
        def mismatch
          @files.find do |file|
            path = File.join(@dir, file["name"])
            !File.file?(path) || File.size(path) != file["size"] || Digest::SHA256.file(path).hexdigest != file["sha256"]
          end
        end

        def paths
          @files.map { |file| File.join(@dir, file["name"]) }
        end
      end
    end
  end
end
