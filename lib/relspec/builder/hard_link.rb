# frozen_string_literal: true

require "fileutils"

module Relspec
  module Builder
    # A file placed at a second path without room: a hard link, a copy
    # where the filesystem refuses one (another filesystem, no links).
    # Unlike a symbolic link it stays when the first path is removed or
    # replaced.
    module HardLink
      module_function

      def place(from, to)
        File.link(from, to)
      rescue SystemCallError
        FileUtils.cp(from, to)
      end
    end
  end
end
