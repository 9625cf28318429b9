# frozen_string_literal: true

require_relative "../../error"

module Relspec
  module Builder
    module Slurm
      # sbatch reads --output (and --error, --input) as a filename pattern:
      # `%j` becomes the job id, `%%` a percent sign, and a name holding a
      # backslash is taken without its backslashes. A project folder named
      # `release-100%j` therefore sent every job's log elsewhere. A path
      # goes to sbatch with each `%` doubled; a backslash, which the
      # pattern cannot keep, is refused with the path.
      module FilePattern
        module_function

        def escape(path)
          if path.include?("\\")
            raise BuildError, "#{path}: Slurm cannot write a job's log to a path holding a backslash " \
                              "(sbatch drops it); build from a folder without one"
          end

          path.gsub("%", "%%")
        end
      end
    end
  end
end
