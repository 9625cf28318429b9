# frozen_string_literal: true

require_relative "../error"
require_relative "../file_lock"
require_relative "../display_path"

module Relspec
  module Builder
    # One relspec process at a time per target folder
    # (<out>/<release>/<codename>-<arch>): `relspec build` holds it while it
    # builds the target, `relspec publish` while it reads the target's
    # build-results.yml and includes what it lists. A second build of the
    # same target would build every package again and both would claim
    # them; a publish during a build could read results whose files the
    # build is replacing. So the second one refuses at once, naming the
    # holder (from /proc/locks). Publishes share the lock with each other
    # (the repository lock makes the second one wait). A flock: the kernel
    # drops it when the holder dies, so a killed run never leaves a stale
    # lock.
    class TargetLock
      FILE_NAME = ".relspec-target.lock"

      # Another process holds the target.
      class Busy < Relspec::Error; end

      # Yields while this process holds +dir+'s lock; +doing+ says what for
      # ("build", "publish") in the refusal the other process gets.
      # +shared+: publishers share it (the repository lock orders them),
      # a build holds it alone.
      def self.hold(dir, doing, shared: false, &block)
        busy = lambda do |file|
          raise Busy, "cannot #{doing} #{DisplayPath.of(dir)}: #{holder(file)} is using it; run again when it has finished"
        end
        FileLock.hold(dir, FILE_NAME, busy: busy, shared: shared, &block)
      rescue FileLock::Unavailable => e
        raise Error, "cannot #{doing} #{DisplayPath.of(dir)}: cannot lock it (#{e.path}: #{e.message})"
      end

      # Who holds +file+'s flock: "relspec build (pid 123)", as far as
      # /proc tells (it may have ended in between).
      def self.holder(file)
        stat = file.stat
        device = format("%02x:%02x:%d", stat.dev_major, stat.dev_minor, stat.ino)
        line = File.foreach("/proc/locks").find { |entry| !entry.include?("->") && entry.split[5] == device }
        pid = line&.split&.fetch(4)&.to_i
        pid ? "#{command_of(pid)} (pid #{pid})" : "another process"
      rescue SystemCallError
        "another process"
      end

      # "relspec build" from the holder's command line, else its program name.
      def self.command_of(pid)
        args = File.binread("/proc/#{pid}/cmdline").split("\0")
        at = args.index { |arg| File.basename(arg) == "relspec" }
        at ? "relspec #{args[at + 1]}" : File.basename(args.first.to_s)
      rescue SystemCallError
        "a process"
      end
      private_class_method :holder, :command_of
    end
  end
end
