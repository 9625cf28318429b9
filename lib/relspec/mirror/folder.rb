# frozen_string_literal: true

require "fileutils"
require_relative "../atomic_file"
require_relative "../error"
require_relative "../display_path"
require_relative "../printable"
require_relative "../unlinked_path"

module Relspec
  module Mirror
    # The folder `relspec mirror SPEC --out DIR` makes its mirror in.
    # relspec rewrites its conf/distributions, includes and removes
    # packages with reprepro and writes its own files there, so it takes
    # only a folder it made: a new one, an empty one (adopted), or one that
    # holds its MARKER, written when it takes the folder. A mirror of an
    # earlier relspec (no marker yet) is known by its mirror.yml beside the
    # conf/distributions relspec writes, and gets the marker. Anything else
    # (a reprepro repository, a folder with a conf/) is refused before
    # anything is written: reprepro would refuse a repository whose
    # distributions relspec rewrote.
    module Folder
      MARKER = ".relspec-mirror"
      MANIFEST = "mirror.yml"
      LABEL = "Label: relspec mirror"
      # What relspec itself writes below the folder (reprepro writes db/,
      # dists/ and pool/): never through a link.
      OWN = ["conf/distributions", "conf/options", ".relspec-incoming"].freeze

      module_function

      # Takes +dir+ for a mirror (made when missing), or raises Error
      # saying why it is not relspec's.
      def claim(dir)
        refuse(dir, "is not a folder") if File.exist?(dir) && !File.directory?(dir)
        FileUtils.mkdir_p(dir)
        why = "relspec mirror writes only inside #{dir} and never through a link; remove the link and run again"
        ([MARKER] + OWN).each { |relative| UnlinkedPath.check(dir, relative, why: why) }
        return if File.file?(File.join(dir, MARKER))

        unless Dir.empty?(dir) || earlier_mirror?(dir)
          refuse(dir, "is not a mirror relspec made (it holds #{listing(dir)} and no #{MARKER})")
        end
        AtomicFile.write(File.join(dir, MARKER), "a field mirror made by relspec mirror\n")
      end

      # A mirror an earlier relspec made, before the marker.
      def earlier_mirror?(dir)
        conf = File.join(dir, "conf", "distributions")
        File.file?(File.join(dir, MANIFEST)) && File.file?(conf) &&
          File.foreach(conf).any? { |line| line.chomp == LABEL }
      end

      def listing(dir)
        names = Dir.children(dir).sort
        shown = names.first(3).map { |name| Printable.text(name) }.join(", ")
        names.size > 3 ? "#{shown}, …" : shown
      end

      def refuse(dir, what)
        raise Error, "--out #{Printable.text(DisplayPath.of(dir))} #{what}: relspec mirror makes a mirror in a new or empty folder " \
                     "and changes only the mirrors it made; choose another --out"
      end
    end
  end
end
