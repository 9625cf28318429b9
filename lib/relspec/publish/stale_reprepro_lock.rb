# frozen_string_literal: true

module Relspec
  module Publish
    # reprepro's own lock is a file, db/lockfile, that it creates on start
    # and deletes on exit: a reprepro killed by a signal it cannot catch
    # (SIGKILL, the OOM killer, a lost machine) leaves it behind, and every
    # later reprepro on the repository waits for it (RepositoryConfig's
    # waitforlock: 5 minutes) and then fails. A publish holds relspec's own
    # flock (RepositoryLock), so no other relspec publisher runs; what may
    # still hold reprepro's lock is a reprepro started by hand. The lock is
    # stale when no live reprepro process uses the repository: none has a
    # file below it open, works in it, or names it as --basedir/-b.
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

        base = File.realpath(repository)
        return nil if live_reprepros(proc_root).any? { |pid_dir| uses?(pid_dir, base) }

        File.delete(lock)
        lock
      rescue Errno::ENOENT
        nil # the reprepro that held it has just finished
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

      def uses?(pid_dir, base)
        cwd = File.readlink(File.join(pid_dir, "cwd"))
        within?(cwd, base) || basedir_argument?(pid_dir, cwd, base) || open_below?(pid_dir, base)
      rescue SystemCallError
        true # cannot tell (gone, or another user's): not stale
      end

      def within?(path, base)
        path == base || path.start_with?("#{base}/")
      end

      def basedir_argument?(pid_dir, cwd, base)
        args = File.read(File.join(pid_dir, "cmdline")).split("\0")
        args.each_with_index.any? do |arg, index|
          value = arg[/\A--basedir=(.+)\z/, 1] || (%w[-b --basedir].include?(arg) ? args[index + 1] : nil)
          value && real(File.expand_path(value, cwd)) == base
        end
      end

      def real(path)
        File.realpath(path)
      rescue SystemCallError
        path
      end

      def open_below?(pid_dir, base)
        Dir.glob(File.join(pid_dir, "fd", "*")).any? do |fd|
          within?(File.readlink(fd), base)
        rescue SystemCallError
          false
        end
      end
    end
  end
end
