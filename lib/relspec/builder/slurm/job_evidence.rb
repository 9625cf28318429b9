# frozen_string_literal: true

require "fileutils"
require_relative "../../output_tree"
require_relative "replaced_files"

module Relspec
  module Builder
    module Slurm
      # The early cutoff's evidence of a Slurm run's builds
      # (docs/scale-out.md, "Early cutoff"): the files of the builds the
      # jobs replace, kept first (ReplacedFiles), and for each job's
      # verified files the ABI dumps, made on this machine from the .debs
      # the job returned — this machine's abidw, as made the dumps they are
      # compared with; a node's own dumps would be one more thing to trust —
      # in a scratch folder, moved beside them, then the verdict decided.
      class JobEvidence
        attr_reader :replaced

        # +run+: the Run; +dumps+: called with (source, files, folder, log)
        # to make the dumps of +files+' .debs into +folder+, returns their
        # paths (Builder::Run's, as for a local build).
        def initialize(run, dumps)
          @run = run
          @dumps = dumps
          @replaced = ReplacedFiles.new(File.join(run.jobs_dir, "replaced"))
        end

        # Keeps the files of +records+ (the builds of the packages the run
        # builds, as build-results.yml has them) before a job replaces them.
        def keep(records)
          @replaced.keep(@run.dir, records)
        end

        # What the Engine does with a job's verified files (+paths+):
        # returns them with the dumps, +verdicts+ deciding the build.
        def take(verdicts)
          lambda do |entry, paths|
            scratch = File.join(@run.jobs_dir, "dumps", entry.source)
            FileUtils.rm_rf(scratch)
            folder = File.join(@run.dir, OutputTree.results_name(entry.source))
            dumps = @dumps.call(entry.source, paths, scratch, @run.log_path(entry.source)).map do |dump|
              File.join(folder, File.basename(dump)).tap { |path| File.rename(dump, path) }
            end
            FileUtils.rm_rf(scratch)
            (paths + dumps).tap { |files| verdicts.decide(entry, files) }
          end
        end

        # The run ended: nothing is compared any more.
        def drop
          @replaced.drop
          FileUtils.rm_rf(File.join(@run.jobs_dir, "dumps"))
        end
      end
    end
  end
end
