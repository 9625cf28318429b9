# frozen_string_literal: true

require_relative "../../output_tree"
require "digest"
require "open3"

module Relspec
  module Builder
    module Slurm
      # The result file a job wrote last (JobScript), checked as a local
      # build's files are (#problem): a built result counts only when every
      # file it lists is in the package's results folder, with the size and
      # SHA256 the node saw, and is of that package.
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
          values = fields.to_h.except("file")
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

        # Why the result cannot be recorded as +source+'s build at +version+
        # (a node is not trusted more than a local build): nil when every
        # listed file is a plain file in results/<source>/ with the bytes
        # the node recorded, there is a .deb, and every .deb, .buildinfo
        # and .changes is of that source and version.
        def problem(source, version)
          return "the job's result lists no file" if @files.empty?

          folder = "#{OutputTree.results_name(source)}/"
          @files.each do |file|
            name = file["name"].to_s
            reason = placement(name, folder) || bytes(name, file) || ownership(name, source, version)
            return reason if reason
          end
          return "the job's result lists no .deb" unless @files.any? { |file| file["name"].end_with?(".deb", ".udeb") }

          nil
        end

        private

        def placement(name, folder)
          base = name.delete_prefix(folder)
          return nil if name.start_with?(folder) && !base.empty? && !base.include?("/") && !%w[. ..].include?(base) &&
                        !base.match?(/[[:cntrl:]]/)

          "#{name.inspect} is not a file of #{folder} (a job's files stay in its package's results folder)"
        end

        def bytes(name, file)
          path = File.join(@dir, name)
          return "#{name} is missing" unless File.lstat(path).file?
          return nil if File.size(path) == file["size"] && Digest::SHA256.file(path).hexdigest == file["sha256"]

          "#{name} is not what the job wrote (size or SHA256 differ; is #{@dir} on a filesystem every node shares?)"
        rescue SystemCallError
          "#{name} is missing"
        end

        # A .deb says its source and version in its control fields; the
        # other files name them in the file name.
        def ownership(name, source, version)
          base = File.basename(name)
          unless base.end_with?(".deb", ".udeb")
            return nil if base.start_with?("#{source}_#{version.sub(/\A\d+:/, '')}_")

            return "#{name} is not a file of #{source} #{version}"
          end
          owner, owner_version = deb_source(File.join(@dir, name))
          return nil if [owner, owner_version] == [source, version]

          "#{name} is a binary package of #{owner || 'no source'} #{owner_version}, not of #{source} #{version}"
        end

        # [source, version] of a .deb; [nil, nil] when it is not readable.
        def deb_source(path)
          output, status = Open3.capture2e("dpkg-deb", "--field", path, "Package", "Source", "Version")
          return [nil, nil] unless status.success?

          fields = output.lines.to_h { |line| line.chomp.split(": ", 2) }
          source = fields["Source"]&.split(" (")&.first || fields["Package"]
          [source, fields["Source"]&.[](/\((.+)\)/, 1) || fields["Version"]]
        rescue SystemCallError
          [nil, nil]
        end

        public

        def paths
          @files.map { |file| File.join(@dir, file["name"]) }
        end
      end
    end
  end
end
