# frozen_string_literal: true

require "open3"
require "tmpdir"
require_relative "../printable"
require_relative "../worker_pool"

module Relspec
  class Catalog
    # The changes to tracked files a checkout holds beyond its commit, which
    # the release leaves out (its .orig is `git archive` of the commit) while
    # autoproj would build them. Read fresh on every plan (one `git status`
    # per checkout; the catalog cache keys on commits, not on working trees).
    # Changes that are exactly the package set's patches, as autoproj
    # applied them at import, are not changes: the release applies them too.
    module UncommittedChanges
      # +paths+: the changed files as `git status` names them (made printable);
      # +patched+: the package set patches the package, and these changes
      # are not exactly its patches (or relspec could not tell).
      Change = Struct.new(:paths, :patched, keyword_init: true) do
        def initialize(**)
          super
          freeze
        end

        # plan's note for package +name+
        def note(name)
          shown = paths.first(SHOWN_PATHS).join(", ")
          shown += " and #{paths.size - SHOWN_PATHS} more" if paths.size > SHOWN_PATHS
          text = "#{name} has uncommitted changes in its checkout (#{shown}): the release is made of its commit, without them"
          patched ? "#{text} (they are not exactly the package set's patches, which the release applies)" : text
        end
      end

      # A checkout's core.fsmonitor names a command git status would run:
      # reading a workspace runs nothing of it.
      NO_MONITOR = %w[-c core.fsmonitor=false].freeze

      # The files a note names at most.
      SHOWN_PATHS = 5

      module_function

      # git processes at once: most of a `git status` is starting git (300
      # checkouts: 1.6-1.8 s one at a time, 1.2-1.3 s four at a time, on
      # this project's loaded 2-core machine).
      THREADS = 4

      # +root+: the workspace; +packages+: Catalog::Package of the release.
      # Returns name => Change for the git checkouts with changes, by name.
      def read(root, packages, threads: THREADS)
        checkouts = packages.select { |package| package.checked_out && package.source_dir && package.vcs.type == "git" }
        found = {}
        lock = Mutex.new
        WorkerPool.new(threads).each(checkouts) do |package|
          change = change_of(File.join(root, package.source_dir), package.patches)
          lock.synchronize { found[package.name] = change } if change
        end
        found.sort.to_h
      end

      def change_of(dir, patches)
        paths = changed_paths(dir)
        return nil if paths.empty?
        return nil if !patches.empty? && only_patches?(dir, patches)

        Change.new(paths: paths.map { |path| Printable.text(path) }.freeze, patched: !patches.empty?)
      end

      def changed_paths(dir)
        return [] unless File.exist?(File.join(dir, ".git"))

        output, status = Open3.capture2("git", *NO_MONITOR, "-C", dir, "status", "--porcelain", "--untracked-files=no",
                                        err: File::NULL)
        return [] unless status.success?

        output.lines.map { |line| line.chomp[3..] }.compact.sort
      end

      # Whether the working tree is the commit with the patches applied
      # (each with its level, in order), compared in a throwaway index.
      def only_patches?(dir, patches)
        Dir.mktmpdir("relspec-patched") do |tmp|
          env = { "GIT_INDEX_FILE" => File.join(tmp, "index") }
          return false unless git(env, dir, "read-tree", "HEAD")
          return false unless patches.all? { |patch| git(env, dir, "apply", "--cached", "-p#{patch.level}", "-", stdin: patch.content) }

          tree = git(env, dir, "write-tree")
          tree && git({}, dir, "diff", "--quiet", tree.strip, "--") ? true : false
        end
      end

      # The command's output when it succeeded, else nil.
      def git(env, dir, *args, stdin: "")
        output, status = Open3.capture2(env, "git", *NO_MONITOR, "-C", dir, *args, stdin_data: stdin, err: File::NULL)
        status.success? ? output : nil
      end
    end
  end
end
