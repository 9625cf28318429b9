# frozen_string_literal: true

require_relative "../printable"
require "find"
require "set"

module Relspec
  module Publish
    # reprepro's own lock is a file, db/lockfile, that it creates on start
    # and deletes on exit: a reprepro killed by a signal it cannot catch
    # (SIGKILL, the OOM killer, a lost machine) leaves it behind, and every
    # later reprepro on the repository waits for it (Reprepro::Config's
    # waitforlock: 5 minutes) and then fails. A publish holds relspec's own
    # flock (RepositoryLock), so no other relspec publisher runs; what may
    # still hold reprepro's lock is a reprepro started by hand. The lock is
    # stale when no live reprepro process uses the repository: none has a
    # file of it open, works in it, or names it as --basedir/-b, whatever
    # path it reaches it by (compared by device and inode, never by name).
    #
    # Limit: a user's processes can only read their own /proc entries; a
    # reprepro of another user on a shared repository is not seen (root
    # sees all).
    module StaleRepreproLock
      PROC = "/proc"

      module_function

      # Removes +repository+'s db/lockfile if it is stale; the removed path,
      # or nil (no lock file, or a live reprepro uses the repository).
      def clear(repository, proc_root: PROC)
        lock = File.join(repository, "db", "lockfile")
        return nil unless File.exist?(lock)

        place = Place.new(repository)
        return nil if live_reprepros(proc_root).any? { |pid_dir| uses?(pid_dir, place) }

        File.delete(lock)
        lock
      rescue Errno::ENOENT
        nil # the reprepro that held it has just finished
      end

      # What a command says when #clear removed +lock+.
      def note(lock)
        "removed reprepro's stale lock #{Printable.text(lock)} (no reprepro uses the repository: one was killed before it could remove it)"
      end

      # The /proc folders of reprepro processes that are alive (a killed
      # one stays a zombie until its parent reaps it; it holds nothing).
      def live_reprepros(proc_root)
        Dir.glob(File.join(proc_root, "[0-9]*")).select do |pid_dir|
          stat = File.read(File.join(pid_dir, "stat"))
          # "pid (comm) state …": comm may hold spaces and parentheses
          stat[/\((.*)\)/m, 1] == "reprepro" && stat[/\)\s+(\S)/, 1] != "Z"
        rescue SystemCallError
          false
        end
      end

      # Paths are read through the process's own /proc links (its cwd, its
      # root, its open files) and compared by device and inode: a process
      # that reaches the repository through a bind mount, another mount
      # namespace or a symbolic link names it by another path.
      def uses?(pid_dir, place)
        place.holds_folder?(File.join(pid_dir, "cwd")) || basedir_argument?(pid_dir, place) || open_below?(pid_dir, place)
      rescue SystemCallError
        true # cannot tell (gone, or another user's): not stale
      end

      def basedir_argument?(pid_dir, place)
        args = File.read(File.join(pid_dir, "cmdline")).split("\0")
        args.each_with_index.any? do |arg, index|
          value = arg[/\A--basedir=(.+)\z/, 1] || (%w[-b --basedir].include?(arg) ? args[index + 1] : nil)
          value && place.same?(File.join(pid_dir, value.start_with?("/") ? "root" : "cwd", value))
        end
      end

      def open_below?(pid_dir, place)
        Dir.glob(File.join(pid_dir, "fd", "*")).any? do |fd|
          place.holds_file?(fd)
        rescue SystemCallError
          false
        end
      end

      # The repository's folder and files by device and inode.
      class Place
        def initialize(repository)
          @repository = repository
          @id = identity(repository)
        end

        def same?(path)
          identity(path) == @id
        rescue SystemCallError
          false
        end

        # +path+ (a folder) is the repository or below it: its parents are
        # walked up through +path+ itself, so in the process's view.
        def holds_folder?(path)
          seen = nil
          64.times do
            id = identity(path)
            return true if id == @id
            return false if id == seen # the root is its own parent

            seen = id
            path = File.join(path, "..")
          end
          false
        end

        def holds_file?(path)
          stat = File.stat(path)
          return holds_folder?(path) if stat.directory?

          files.include?([stat.dev, stat.ino])
        end

        private

        def identity(path)
          stat = File.stat(path)
          [stat.dev, stat.ino]
        end

        # Every file below the repository, read once.
        def files
          @files ||= begin
            found = Set.new
            Find.find(@repository) do |path|
              stat = File.lstat(path)
              found << [stat.dev, stat.ino] if stat.file?
            rescue SystemCallError
              nil
            end
            found
          end
        end
      end
    end
  end
end
