# frozen_string_literal: true

require_relative "scheduler"
require_relative "build_plan"

module Relspec
  module Builder
    # The early cutoff acting in one local run (docs/abi.md, "Early
    # cutoff"). A candidate is decided when it is ready to build: its
    # closure is built then, so the verdicts it goes by exist; a kept one is
    # not built at all. A package built in the run whose closure holds a
    # kept one was compiled naming the kept package's new version (compile
    # runs before any decision), which the repository would never hold: the
    # kept package is built after all, first, and its keep revoked.
    # Thread-safe: builds run in worker threads.
    class EarlyCutoff
      # +verdicts+: Abi::InterfaceVerdicts (or NoVerdicts: nothing kept);
      # +entries+: the plan's; +kept+: the sources an earlier run kept at
      # their planned versions.
      def initialize(verdicts, entries, kept: [])
        @verdicts = verdicts
        @entries = entries.to_h { |entry| [entry.source, entry] }
        @kept = kept.to_h { |source| [source, true] }
        @building = Hash.new { |hash, source| hash[source] = Mutex.new }
        @revoked = []
        @lock = Mutex.new
      end

      # Why a kept package is built after all: +source+, built in the
      # run, names its new version (the Slurm engine says it too).
      def self.built_after_all(source)
        "built after all: #{source} is built in this run and names its new version"
      end

      # True when the cutoff keeps +entry+: it is not built.
      def keep?(entry)
        return false unless @verdicts.keep(entry)&.keep?

        @lock.synchronize { @kept[entry.source] = true }
      end

      # Builds, before +entry+, each kept package of its closure, once
      # (a dependent building at the same time waits for it): yields the
      # kept entry and returns nothing; a failure raises, naming it.
      def build_kept_for(entry, &block)
        closure(entry.source).each do |source|
          @lock.synchronize { @building[source] }.synchronize do
            next unless @lock.synchronize { @kept[source] }

            revoke(@entries.fetch(source), entry, &block)
          end
        end
      end

      # The outcomes of the kept packages built after all since the last
      # call, for the caller to record (Scheduler::Outcome).
      def drain
        @lock.synchronize { @revoked.slice!(0..) }
      end

      private

      def revoke(kept, entry)
        started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
        @verdicts.revoke(kept.source, EarlyCutoff.built_after_all(entry.source))
        outcome = begin
          Scheduler::Outcome.new(entry: kept, status: :built, value: yield(kept))
        rescue Relspec::Error => e
          Scheduler::Outcome.new(entry: kept, status: :failed, reason: e.message)
        end
        outcome.duration = (Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).round(1)
        @lock.synchronize do
          @kept.delete(kept.source)
          @revoked << outcome
        end
        raise BuildError, "build-dependency #{kept.source} failed" if outcome.status == :failed
      end

      def closure(source)
        BuildPlan.closure(@entries, source)
      end
    end
  end
end
