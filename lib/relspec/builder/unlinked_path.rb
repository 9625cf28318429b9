# frozen_string_literal: true

require_relative "../error"
require_relative "../unlinked_path"

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
      # on the way (Relspec::UnlinkedPath). Returns the joined path.
      def check(base, relative)
        Relspec::UnlinkedPath.check(base, relative, error: BuildError,
                                                    why: "a build writes only inside #{base} and never through a " \
                                                         "link; remove the link and build again")
      end
    end
  end
end
