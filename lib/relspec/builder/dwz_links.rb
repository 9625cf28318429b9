# frozen_string_literal: true

require "fileutils"
require_relative "../elf_file"

module Relspec
  module Builder
    # A package whose .debs ship several ELF files (a library and its Ruby
    # extension, say) gets a dwz "multifile": the debug information they
    # share, in usr/lib/debug/.dwz/<triplet>/<package>.debug, which each
    # .debug file names by the absolute path /usr/lib/debug/.dwz/… and by
    # its build id. Unpacked anywhere but /, abidw finds it only through
    # <debug root>/.build-id/<xx>/<rest>.debug, which no .deb ships: without
    # it abidw fails (exit 1, no message) and the library has no ABI dump.
    # DwzLinks adds that link for every multifile below a debug root.
    module DwzLinks
      # Adds the .build-id link of each multifile below +debug_root+ (an
      # unpacked usr/lib/debug) that has none; returns the links made.
      def self.add(debug_root)
        Dir.glob(File.join(debug_root, ".dwz", "**", "*")).sort.filter_map do |path|
          next if File.symlink?(path) || !File.file?(path)

          link(debug_root, path, ElfFile.build_id(File.binread(path)))
        end
      end

      def self.link(debug_root, path, id)
        return nil unless id

        link = File.join(debug_root, ".build-id", id[0, 2], "#{id[2..]}.debug")
        return nil if File.exist?(link) || File.symlink?(link)

        FileUtils.mkdir_p(File.dirname(link))
        File.symlink(File.expand_path(path), link)
        link
      end

      private_class_method :link
    end
  end
end
