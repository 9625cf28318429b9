# frozen_string_literal: true

module Relspec
  module Builder
    # Runs builds in dependency order: a package starts as soon as every
    # package of its build-dependency closure in the plan is done (not wave
    # by wave), up to +jobs+ at once. The closure, not only the direct
    # build-dependencies: a backend installs the whole closure, and a
    # dependency's dependency rebuilt in the same run (its files were
    # damaged, say) must be there before. A failed package's reverse dependencies are skipped,
    # naming the failed package; the others go on with +keep_going+, else
    # nothing new starts after the first failure.
    #
    # An interrupt (SIGINT) reaches the calling thread while it waits; the
    # caller stops the running tools, whose threads then end on their own.
    #
    # The scheduler knows nothing of Debian or backends: it hands each entry
    # to the block (in a worker thread) and reports every outcome to
    # +on_done+ in the calling thread, one at a time.
    class Scheduler
      # +status+: :built, :kept (Done), :failed or :skipped; +value+: the block's return
      # value (built), +reason+: why it failed or was skipped.
      Outcome = Struct.new(:entry, :status, :value, :reason, :duration, keyword_init: true)
      # What the block returns for a success of another +status+ than
      # :built (the early cutoff's :kept): its dependents go on as after a
      # build.
      Done = Struct.new(:status, :value, keyword_init: true)
      SUCCESSES = %i[built kept].freeze

      # +entries+: objects with #source and #build_depends (source names);
      # +done+: sources already built (from an earlier run).
      def initialize(entries, jobs:, keep_going: false, done: [])
        @entries = entries
        @jobs = [jobs.to_i, 1].max
        @keep_going = keep_going
        @done = done.to_h { |source| [source, true] }
        by_source = entries.to_h { |entry| [entry.source, entry] }
        @needs = {}
        entries.each { |entry| closure(entry, by_source) }
      end

      # Yields each entry to build; the block returns a value or raises a
      # Relspec::Error (the failure's reason). Returns the outcomes in the
      # order they finished.
      def run(on_start: nil, on_done: nil, &build)
        pending = @entries.reject { |entry| @done[entry.source] }
        wanted = pending.to_h { |entry| [entry.source, true] }
        finished = Queue.new
        running = {}
        failed = {} # source => the failed package it goes back to
        outcomes = []
        stopped = false
        until pending.empty? && running.empty?
          unless stopped
            ready(pending, wanted, running, failed).each do |entry|
              break if running.size >= @jobs

              pending.delete(entry)
              on_start&.call(entry)
              running[entry.source] = start(entry, finished, &build)
            end
          end
          skip_dependents(pending, failed).each do |outcome|
            outcomes << outcome
            on_done&.call(outcome)
          end
          break if pending.empty? && running.empty?

          if running.empty? && stopped
            pending.each do |entry|
              outcome = Outcome.new(entry: entry, status: :skipped,
                                    reason: "not started: the run stopped after #{failed.values.uniq.sort.join(', ')} " \
                                            "failed (--keep-going builds the rest)")
              outcomes << outcome
              on_done&.call(outcome)
            end
            break
          end

          outcome = finished.pop
          running.delete(outcome.entry.source)&.join
          raise outcome.value if outcome.status == :crashed

          if SUCCESSES.include?(outcome.status)
            wanted.delete(outcome.entry.source)
          else
            failed[outcome.entry.source] = outcome.entry.source
            stopped = true unless @keep_going
          end
          outcomes << outcome
          on_done&.call(outcome)
        end
        outcomes
      end

      private

      # Entries whose build-dependencies in the plan are all built, in plan
      # order. With nothing running and nothing ready (a dependency cycle,
      # which autoproj refuses but a snapshot might hold), the first one goes.
      def ready(pending, wanted, running, failed)
        candidates = pending.reject { |entry| @needs[entry.source].any? { |dep| failed[dep] } }
        list = candidates.select { |entry| @needs[entry.source].none? { |dep| wanted[dep] } }
        list = candidates.first(1) if list.empty? && running.empty? && !candidates.empty?
        list
      end

      # Pending entries that depend on a failed or skipped one: skipped,
      # naming the failed package at the root (transitively).
      def skip_dependents(pending, failed)
        skipped = []
        loop do
          entry = pending.find { |candidate| @needs[candidate.source].any? { |dep| failed[dep] } }
          break unless entry

          root = failed[@needs[entry.source].find { |dep| failed[dep] }]
          pending.delete(entry)
          failed[entry.source] = root
          skipped << Outcome.new(entry: entry, status: :skipped, reason: "build-dependency #{root} failed")
        end
        skipped
      end

      # The sources in the plan that +entry+ needs built, directly or
      # through others, in plan order of discovery; a cycle (see #ready)
      # ends where it closes and never names the entry itself.
      def closure(entry, by_source, visiting = {})
        @needs.fetch(entry.source) do
          visiting[entry.source] = true
          found = entry.build_depends.select { |dep| by_source.key?(dep) }.flat_map do |dep|
            visiting[dep] ? [dep] : [dep, *closure(by_source[dep], by_source, visiting)]
          end
          visiting.delete(entry.source)
          @needs[entry.source] = (found.uniq - [entry.source]).freeze
        end
      end

      def start(entry, finished)
        Thread.new do
          Thread.current.report_on_exception = false
          started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
          outcome = begin
            value = yield(entry)
            value.is_a?(Done) ? Outcome.new(entry: entry, status: value.status, value: value.value) : Outcome.new(entry: entry, status: :built, value: value)
          rescue Relspec::Error => e
            Outcome.new(entry: entry, status: :failed, reason: e.message)
          rescue StandardError => e # a bug: raised again in the calling thread
            Outcome.new(entry: entry, status: :crashed, value: e)
          end
          outcome.duration = (Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).round(1)
          finished << outcome
        end
      end
    end
  end
end
