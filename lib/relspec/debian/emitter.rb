# frozen_string_literal: true

require_relative "../error"
require_relative "../worker_pool"

module Relspec
  module Debian
    # Writes source packages into their folders, +jobs+ at a time (each is
    # dpkg-source and tar work) on a WorkerPool. A package whose files are
    # already there is left as it is (SourcePackage#emit says which). Every
    # package is tried; the diagnostics of all that failed are raised
    # together, any other error after the others have finished.
    class Emitter
      # +written+, +unchanged+: the folders, sorted; +repaired+: orig cache
      # entries found damaged and made again.
      Result = Struct.new(:written, :unchanged, :repaired, keyword_init: true)

      # +progress+ is called with (done, total) after each package.
      def initialize(jobs:, progress: nil)
        @jobs = jobs
        @progress = progress
      end

      # +packages+: [[dir, SourcePackage]].
      def call(packages)
        written = []
        unchanged = []
        errors = []
        repaired = []
        lock = Mutex.new
        WorkerPool.new(@jobs).each(packages) do |(dir, package)|
          changed = package.emit(dir)
          lock.synchronize do
            (changed ? written : unchanged) << dir
            repaired.concat(package.repaired)
            @progress&.call(written.size + unchanged.size, packages.size)
          end
        rescue InvalidInput => e
          lock.synchronize { errors.concat(e.diagnostics) }
        end
        raise InvalidInput, errors unless errors.empty?

        Result.new(written: written.sort, unchanged: unchanged.sort, repaired: repaired.uniq.sort)
      end
    end
  end
end
