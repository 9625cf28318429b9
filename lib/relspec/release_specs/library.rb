# frozen_string_literal: true

require_relative "spec_file"
require_relative "names"

module Relspec
  module ReleaseSpec
    # The specs/ folder: one <release>.yml per release. Parents are looked up
    # here by name; each file is read and checked once per run.
    class Library
      EXTENSION = ".yml"

      attr_reader :dir

      def initialize(dir)
        @dir = dir
        @files = {}
      end

      # Release names that have a spec file, sorted.
      def names
        Dir.children(dir).select { |entry| entry.end_with?(EXTENSION) }.map { |entry| entry.delete_suffix(EXTENSION) }.sort
      rescue SystemCallError
        []
      end

      def paths
        names.map { |name| path_for(name) }
      end

      def path_for(name)
        file = "#{name}#{EXTENSION}"
        dir == "." ? file : File.join(dir, file)
      end

      # Names that are not release names never become paths (`../x`).
      def include?(name)
        Names.release?(name) && File.file?(path_for(name))
      end

      # The spec file of release +name+, or nil when specs/ has none.
      def find(name)
        include?(name) ? load(path_for(name)) : nil
      end

      def load(path)
        @files[File.expand_path(path)] ||= SpecFile.load(path)
      end

      # Every file read so far, in a stable order.
      def loaded
        @files.keys.sort.map { |key| @files[key] }
      end
    end
  end
end
