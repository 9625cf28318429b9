# frozen_string_literal: true

require "fileutils"
require_relative "../output_tree"
require_relative "unlinked_path"

module Relspec
  module Builder
    # Where one build's files go: a staging folder (results/.<source>.partial)
    # that takes the place of results/<source> only once the build
    # succeeded. A rebuild that fails or is interrupted (Ctrl-C, a killed
    # run) leaves the previous build's files where its record says they are,
    # so the record stays true and publish can still check it (the core
    # release's run 2 lost base/numeric's .debs that way while its record
    # stayed).
    class StagedResults
      attr_reader :staging, :final

      # +dir+: the target's folder; +source+: the source package.
      def initialize(dir, source)
        @final = UnlinkedPath.check(dir, OutputTree.results_name(source))
        @staging = UnlinkedPath.check(dir, OutputTree.staging_name(source))
      end

      # An empty staging folder (what an interrupted run left is removed).
      def prepare
        FileUtils.rm_rf(@staging)
        FileUtils.mkdir_p(@staging)
        @staging
      end

      # Puts the staged files in place of the previous ones; +files+: their
      # staged paths. Returns their final paths.
      def settle(files)
        FileUtils.rm_rf(@final)
        File.rename(@staging, @final)
        files.map { |file| File.join(@final, file.delete_prefix("#{@staging}/")) }
      end
    end
  end
end
