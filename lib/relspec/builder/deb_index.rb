# frozen_string_literal: true

require "fileutils"
require_relative "../apt/deb822"
require_relative "hard_link"

module Relspec
  module Builder
    # A build's own .debs (sbuild's --extra-package) as a flat apt archive
    # in a folder of its own, so that apt resolves with them as sbuild does
    # (DependencyLayers) and a chroot can install them from there: the
    # files are linked in (copied across file systems), as a symlink would
    # point out of the chroot.
    class DebIndex
      attr_reader :dir

      # +scratch+: an empty folder of the caller's; +debs+: .deb files (the
      # first of each name wins, as they are the same file).
      def initialize(scratch, debs)
        @scratch = scratch
        @dir = File.join(scratch, "debs")
        Dir.mkdir(@dir, 0o755)
        debs.uniq { |deb| File.basename(deb) }.each { |deb| HardLink.place(deb, File.join(@dir, File.basename(deb))) }
        @files = nil
      end

      # The sources.list of the archive.
      def sources
        path = File.join(@scratch, "debs.list")
        File.write(path, "deb [trusted=yes] file:#{@dir} ./\n") unless File.file?(path)
        path
      end

      # The command that writes the archive's index and fetches it into
      # +lists+ with this machine's apt-get, reading the chroot at +root+
      # and writing nothing there (its cache and log in +scratch+).
      def update_command(root, lists, scratch)
        FileUtils.mkdir_p([File.join(lists, "partial"), File.join(scratch, "cache", "archives", "partial")])
        ["sh", "-c", 'cd "$1" && apt-ftparchive packages . > Packages && shift && exec "$@"', "sh", @dir,
         "apt-get", "-o", "Dir=#{root}/", "-o", "Dir::Etc::sourcelist=#{sources}",
         "-o", "Dir::Etc::sourceparts=#{File.join(scratch, 'no-parts')}", "-o", "Dir::State::Lists=#{lists}",
         "-o", "Dir::Cache=#{File.join(scratch, 'cache')}", "-o", "Dir::Log=#{scratch}", "-o", "Debug::NoLocking=1",
         "update"]
      end

      # The archive's file of +package+ (a BuildDependencySet::Package),
      # nil when it is none of the build's .debs.
      def file(package)
        @files ||= Apt::Deb822.parse(File.read(File.join(@dir, "Packages"))).to_h do |fields|
          [fields.values_at("Package", "Version", "Architecture"), File.basename(fields.fetch("Filename"))]
        end
        @files[[package.name, package.version, package.arch]]
      end
    end
  end
end
