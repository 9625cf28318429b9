# frozen_string_literal: true

require "fileutils"
require_relative "../hard_link"

module Relspec
  module Builder
    module Slurm
      # The files of the builds a Slurm run replaces, kept for the early
      # cutoff's verdicts (Abi::InterfaceVerdicts compares a new build with
      # the one it replaces): a job puts its files in place of the old ones
      # itself, on the node, before relspec takes its build, so the old
      # ones are linked here first, under their recorded names
      # (<root>/results/<source>/…). A relspec killed and run again on the
      # same plan finds them here; the run removes them when it ends.
      class ReplacedFiles
        attr_reader :root

        # +root+: a folder of the run (Run#jobs_dir/replaced).
        def initialize(root)
          @root = root
        end

        # Keeps the files +records+ (BuildResults::Record, or nil) list that
        # are in +dir+ with their recorded bytes; a file already kept with
        # those bytes stays (the run adopted: +dir+ may hold new ones).
        def keep(dir, records)
          records.compact.select { |record| record.built? || record.kept? }.flat_map(&:files).each do |file|
            next if file.intact?(@root) || !file.intact?(dir)

            path = File.join(@root, file.name)
            FileUtils.mkdir_p(File.dirname(path))
            FileUtils.rm_f(path)
            # no room while the job has not replaced the file
            HardLink.place(File.join(dir, file.name), path)
          end
        end

        # The run ended: nothing is compared any more.
        def drop
          FileUtils.rm_rf(@root)
        end
      end
    end
  end
end
