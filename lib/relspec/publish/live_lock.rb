# frozen_string_literal: true

require "fileutils"
require "securerandom"
require_relative "../error"
require_relative "stale_reprepro_lock"

module Relspec
  module Publish
    # reprepro's own lock on the live database, held by relspec while it
    # works on its copy (Transaction): db/lockfile, made the way reprepro
    # makes it (created only if absent), so that a reprepro started by hand
    # meanwhile waits instead of changing the database the publish is about
    # to replace. A lock file that no live reprepro uses is stale
    # (StaleRepreproLock) and removed; one a reprepro holds is waited for.
    class LiveLock
      POLL = 0.5 # seconds between two tries
      WAIT = 300 # seconds a reprepro's lock is waited for, as long as reprepro waits (Reprepro::Config)

      # +clock+: monotonic seconds; +pause+: sleeps (both for tests).
      def initialize(repository, wait: WAIT, waiting: nil, clock: -> { Process.clock_gettime(Process::CLOCK_MONOTONIC) },
                     pause: ->(seconds) { sleep(seconds) })
        @repository = repository
        @path = File.join(repository, "db", "lockfile")
        @wait = wait
        @waiting = waiting
        @clock = clock
        @pause = pause
      end

      attr_reader :path

      # Takes the lock; the stale lock file it removed on the way, or nil.
      def take
        @made_folder = !File.directory?(File.dirname(@path))
        FileUtils.mkdir_p(File.dirname(@path))
        deadline = @clock.call + @wait
        stale = nil
        until create
          removed = StaleRepreproLock.clear(@repository)
          stale ||= removed
          next if removed

          give_up if @clock.call > deadline
          @waiting&.call("the reprepro holding #{@path}") unless @told
          @told = true
          @pause.call(POLL)
        end
        stale
      rescue SystemCallError => e
        raise PublishError, "cannot lock #{@path}: #{e.message.sub(/ @ .*/, '')}"
      end

      # Removes the lock file if it is still the one taken (a switched-in
      # database has none of its own; a reprepro may have locked it since),
      # and the db/ folder #take made if nothing was switched in (a first
      # publish that failed).
      def release
        File.delete(@path) if @text && File.exist?(@path) && File.read(@path) == @text
        Dir.rmdir(File.dirname(@path)) if @made_folder && Dir.empty?(File.dirname(@path))
      rescue SystemCallError
        nil
      end

      private

      def give_up
        raise PublishError, "#{@path}: reprepro is still working on #{@repository} after #{@wait} s; wait for it " \
                            "to end, then publish again"
      end

      def create
        text = "relspec publish #{Process.pid} #{SecureRandom.hex(8)}\n"
        File.open(@path, File::WRONLY | File::CREAT | File::EXCL, 0o600) { |file| file.write(text) }
        @text = text
        true
      rescue Errno::EEXIST
        false
      end
    end
  end
end
