# frozen_string_literal: true

require "fileutils"

module Relspec
  module Builder
    # What a Debian build leaves next to the unpacked source (the binary
    # packages, .buildinfo and .changes), moved where the results live.
    module ProducedFiles
      PATTERN = "*.{deb,udeb,buildinfo,changes}"

      module_function

      # The moved files' paths, sorted.
      def collect(work, output_dir)
        FileUtils.mkdir_p(output_dir)
        Dir.glob(File.join(work, PATTERN)).sort.map do |file|
          target = File.join(output_dir, File.basename(file))
          FileUtils.mv(file, target)
          target
        end
      end
    end
  end
end
