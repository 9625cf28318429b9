# frozen_string_literal: true

require_relative "../error"
require_relative "../file_lock"
require_relative "../display_path"
require_relative "../lock_holder"

module Relspec
  module Builder
    # One relspec process at a time per target folder
    # (<out>/<release>/<codename>-<arch>): `relspec build` holds it while it
    # builds the target, `relspec publish` while it reads the target's
    # build-results.yml and includes what it lists. A second build of the
    # same target would build every package again and both would claim
    # them; a publish during a build could read results whose files the
    # build is replacing. So the second one refuses at once, naming the
    # holder and since when (LockHolder). Publishes share the lock with each other
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
          raise Busy, "cannot #{doing} #{DisplayPath.of(dir)}: #{LockHolder.of(file)} is using it; run again when it has finished"
        end
        FileLock.hold(dir, FILE_NAME, busy: busy, shared: shared, &block)
      rescue FileLock::Unavailable => e
        raise Error, "cannot #{doing} #{DisplayPath.of(dir)}: cannot lock it (#{e.path}: #{e.message})"
      end
    end
  end
end
