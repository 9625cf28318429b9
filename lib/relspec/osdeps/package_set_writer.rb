# frozen_string_literal: true

require "fileutils"
require_relative "../atomic_file"
require_relative "../error"

module Relspec
  module Osdeps
    # Puts a package set ({relative path => content}) into its folder, which
    # belongs to the maintainer (docs/releasing.md keeps it as a git
    # repository): only relspec's own files are touched. Each file is
    # replaced by rename and only when its bytes change; lib/ and data/ are
    # relspec's as a whole (a file there that the package set no longer
    # has is removed); .git and every other file the maintainer put beside
    # them stay. A symbolic link where relspec writes is refused: writing
    # through it would change a file outside the folder.
    module PackageSetWriter
      # Folders whose every file relspec wrote.
      OWNED = %w[lib data].freeze

      # +written+: paths whose content changed, +removed+: relspec's files
      # the package set no longer has.
      Result = Struct.new(:written, :removed, keyword_init: true) do
        def changed?
          !(written.empty? && removed.empty?)
        end
      end

      module_function

      def write(dir, files)
        refuse_links(dir, files)
        stale = owned_files(dir) - files.keys
        written = files.select do |path, content|
          FileUtils.mkdir_p(File.dirname(File.join(dir, path)))
          AtomicFile.update(File.join(dir, path), content)
        end.keys
        stale.each { |path| File.delete(File.join(dir, path)) }
        remove_empty_folders(dir)
        Result.new(written: written, removed: stale)
      end

      def owned_files(dir)
        OWNED.flat_map do |folder|
          Dir.glob("**/*", File::FNM_DOTMATCH, base: File.join(dir, folder))
             .map { |path| File.join(folder, path) }
             .select { |path| File.file?(File.join(dir, path)) }
        end.sort
      end

      def refuse_links(dir, files)
        paths = files.keys.flat_map { |path| ascending(path) }.uniq
        link = paths.find { |path| File.symlink?(File.join(dir, path)) }
        return unless link

        raise Error, "#{File.join(dir, link)} is a symbolic link: the package set writes its own files only, " \
                     "remove it or choose another --out"
      end

      # "a/b/c" → ["a", "a/b", "a/b/c"]
      def ascending(path)
        parts = path.split("/")
        parts.each_index.map { |index| parts[0..index].join("/") }
      end

      def remove_empty_folders(dir)
        OWNED.each do |folder|
          Dir.glob("**/", base: File.join(dir, folder)).sort_by { |path| -path.length }.each do |path|
            full = File.join(dir, folder, path)
            Dir.rmdir(full) if Dir.empty?(full)
          end
        end
      end
    end
  end
end
