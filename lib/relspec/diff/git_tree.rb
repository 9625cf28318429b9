# frozen_string_literal: true

require "open3"
require_relative "../error"

module Relspec
  module Diff
    # Files of a project as they were at a git ref, read with `git show` and
    # `git ls-tree`, never by checking anything out: the working tree and
    # the index are not touched. Paths are relative to +root+ (the project
    # folder, which may be below the repository's top).
    class GitTree
      # Keeps `git diff` from refreshing the index: reading must write nothing.
      READ_ONLY = { "GIT_OPTIONAL_LOCKS" => "0" }.freeze

      attr_reader :ref

      def initialize(root, ref)
        @root = root
        @ref = ref
        _, status = git("rev-parse", "--verify", "--quiet", "#{ref}^{commit}")
        raise InvalidOption, "#{ref} is not a commit of the git repository at #{root}" unless status.success?
      end

      # The file's text at the ref, or nil when it did not exist there.
      def read(path)
        out, status = git("show", "#{@ref}:./#{path}")
        status.success? ? out : nil
      end

      # The names of the files directly in +dir+ at the ref.
      def files(dir)
        out, status = git("ls-tree", "--name-only", @ref, "--", "#{dir}/")
        status.success? ? out.lines.map { |line| File.basename(line.chomp) }.sort : []
      end

      # old path => new path of the files of +dir+ git sees renamed between
      # the ref and the working tree.
      def renames(dir)
        out, status = git("diff", "--name-status", "--find-renames", "--relative", @ref, "--", "#{dir}/")
        return {} unless status.success?

        out.lines.filter_map do |line|
          kind, old, new = line.chomp.split("\t")
          [old, new] if kind.start_with?("R")
        end.to_h
      end

      def describe(path)
        "#{@ref}:#{path}"
      end

      private

      def git(*args)
        out, _err, status = Open3.capture3(READ_ONLY, "git", "-C", @root, *args)
        [out, status]
      rescue SystemCallError => e
        raise Error, "cannot run git: #{e.message}"
      end
    end
  end
end
