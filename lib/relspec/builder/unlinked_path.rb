# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Builder
    # A path below a target folder that a build writes or deletes (logs/,
    # logs/<source>.log, results/, results/<source>/) must not lead out of
    # it through a symbolic link: writing a log through logs/<source>.log
    # would overwrite the file it points to, and emptying results/<source>/
    # would delete the files of the folder results/ points to.
    module UnlinkedPath
      module_function

      # +relative+ below +base+; raises BuildError naming the first link
      # on the way (existing parts only: what is missing is made later,
      # by relspec, as a plain folder or file). Returns the joined path.
      def check(base, relative)
        path = base
        relative.split("/").each do |part|
          path = File.join(path, part)
          next unless File.symlink?(path)

          raise BuildError, "#{path} is a symbolic link (to #{File.readlink(path)}): a build writes only inside " \
                            "#{base} and never through a link; remove the link and build again"
        end
        File.join(base, relative)
      end
    end
  end
end
