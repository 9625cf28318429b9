# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Debian
    # Writes source packages into their folders, +jobs+ at a time (each is
    # dpkg-source and tar work). A package whose files are already there
    # is left as it is (SourcePackage#emit says which). Every package is
    # tried; the diagnostics of all that failed are raised together, any
    # other error after the others have finished.
    class Emitter
      # +written+, +unchanged+: the folders, sorted; +repaired+: orig cache
      # entries found damaged and made again.
      Result = Struct.new(:written, :unchanged, :repaired, keyword_init: true)

      # +progress+ is called with (done, total) after each package.
      def initialize(jobs:, progress: nil)
        @jobs = [jobs.to_i, 1].max
        @progress = progress
      end

      # +packages+: [[dir, SourcePackage]].
      def call(packages)
        queue = Queue.new
        packages.each { |job| queue << job }
        written = []
        unchanged = []
        errors = []
        repaired = []
        lock = Mutex.new
        failures = []
        Array.new([@jobs, packages.size].min) do
          Thread.new do
            Thread.current.report_on_exception = false
            while (job = next_job(queue))
              dir, package = job
              begin
                changed = package.emit(dir)
                lock.synchronize do
                  (changed ? written : unchanged) << dir
                  repaired.concat(package.repaired)
                  @progress&.call(written.size + unchanged.size, packages.size)
                end
              rescue InvalidInput => e
                lock.synchronize { errors.concat(e.diagnostics) }
              rescue StandardError => e # re-raised below, in the main thread, where errors become messages
                lock.synchronize { failures << e }
              end
            end
          end
        end.each(&:join)
        raise failures.first unless failures.empty?
        raise InvalidInput, errors unless errors.empty?

        Result.new(written: written.sort, unchanged: unchanged.sort, repaired: repaired.uniq.sort)
      end

      private

      def next_job(queue)
        queue.pop(true)
      rescue ThreadError
        nil
      end
    end
  end
end
