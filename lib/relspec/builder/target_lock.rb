# frozen_string_literal: true

require "fileutils"
require_relative "../error"
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
      def self.hold(dir, doing, shared: false)
        FileUtils.mkdir_p(dir)
        file = File.open(File.join(dir, FILE_NAME), File::RDWR | File::CREAT, 0o644)
        begin
          unless file.flock((shared ? File::LOCK_SH : File::LOCK_EX) | File::LOCK_NB)
            raise Busy, "cannot #{doing} #{DisplayPath.of(dir)}: #{LockHolder.of(file)} is using it; run again when it has finished"
          end

          yield
        ensure
          file.close
        end
      end
    end
  end
end
