# frozen_string_literal: true

require_relative "page"
require_relative "folder"
require_relative "first_error"
require_relative "critical_path"
require_relative "../unlinked_path"
require_relative "../diff/lock_view"
require_relative "../diff/release_diff"
require_relative "../diff/commit_counter"

module Relspec
  module Report
    # Builds the Page of a release from what relspec wrote: the lock (the
    # decisions and their causes), each target's plan.yml (sources and their
    # build-dependencies) and build-results.yml (the last build), the logs
    # (first error lines) and, when there is one, the ancestor's lock (the
    # changes, by the diff's own comparison).
    class Reading
      # A log read through a link (the log, logs/ or a folder on its way)
      # could put any file of this machine on the page and next to a
      # published repository: refused, as a build refuses to write one.
      LINKED_LOG = "the report reads a build's logs only inside %s, never through a link; remove the link and " \
                   "build again"

      # +lock+, +ancestor_lock+: Plan::Lock (the latter nil when there is
      # none); +ancestor+: its release; +inputs+: TargetBuild per target; +abi+:
      # target name => AbiSummary (a target without one shows no verdicts).
      def initialize(lock:, inputs:, ancestor: nil, ancestor_lock: nil, abi: {}, counter: Diff::CommitCounter.new)
        @lock = lock
        @abi = abi
        @inputs = inputs
        @ancestor = ancestor_lock && ancestor
        @diff = ancestor_lock && Diff::ReleaseDiff.compare(snapshot(ancestor_lock), snapshot(lock), counter: counter)
      end

      # The Page, and the logs it links to: link => file on disk.
      def page
        logs = {}
        targets = @inputs.sort_by { |input| input.target.to_s }.map { |input| target_view(input, logs) }
        [Page.new(release: @lock.release, ancestor: @ancestor, targets: targets.freeze).freeze, logs.freeze]
      end

      private

      def snapshot(lock)
        Diff::LockView.snapshot(lock, source: "releases/#{lock.release}/lock.yml")
      end

      def target_view(input, logs)
        name = input.target.to_s
        entries = input.plan ? input.plan.entries : []
        records = input.results ? input.results.entries.to_h { |record| [record.package, record] } : {}
        blocked = blocked_by(entries, records)
        cells = @lock.targets.fetch(name, {}).map do |package, entry|
          cell(input, package, entry, entries.find { |one| one.package == package }, records[package], blocked, logs)
        end
        durations = records.values.select(&:duration).to_h { |record| [record.source, record.duration] }
        TargetView.new(target: name, backend: input.results&.backend, cells: cells.freeze, totals: totals(cells),
                       build_seconds: durations.values.sum, blockers: blockers(cells),
                       critical_path: CriticalPath.of(entries, durations).freeze, changes: changes(name),
                       abi: @abi[name]).freeze
      end

      def cell(input, package, entry, planned, record, blocked, logs)
        source = record&.source || planned&.source
        log = record&.log && UnlinkedPath.check(input.dir, record.log, why: LINKED_LOG % input.dir)
        link = log && File.file?(log) ? "#{Folder::LOGS}/#{input.target.dir_name}/#{File.basename(log)}" : nil
        logs[link] = log if link
        failed = record&.status == "failed"
        Cell.new(package: package, source: source, decision: entry.decision, from: entry.from, version: entry.version,
                 status: status(entry, record), reason: reason(entry, record), blocked_by: blocked[source],
                 duration: record&.duration, log: link,
                 first_error: failed ? FirstError.of_file(log) || FirstError.clean(record.reason.to_s.lines.first.to_s) : nil,
                 causes: entry.causes&.dup&.freeze).freeze
      end

      # Why a build failed or was skipped; why the early cutoff kept one
      # (docs/abi.md), as its build decided it or as the lock records it.
      def reason(entry, record)
        return "kept at #{record.cutoff.keeps}: #{record.cutoff.summary}" if record&.kept?
        return "kept at #{entry.version}: #{entry.kept}" if entry.kept && !record

        record&.reason&.lines&.first&.strip
      end

      def status(entry, record)
        return record.status if record
        return "kept" if entry.kept
        return "published" if entry.decision == "published"

        entry.decision == "build" ? "not built yet" : nil
      end

      # source => the failed sources a skipped build waited for, through its
      # build-dependencies (plan.yml lists them before their users).
      def blocked_by(entries, records)
        status = records.values.to_h { |record| [record.source, record.status] }
        waits = {}
        entries.each do |entry|
          waits[entry.source] = entry.build_depends.flat_map do |need|
            status[need] == "failed" ? [need] : waits.fetch(need, [])
          end.uniq.sort.freeze
        end
        entries.select { |entry| status[entry.source] == "skipped" && !waits[entry.source].empty? }
               .to_h { |entry| [entry.source, waits[entry.source]] }
      end

      def blockers(cells)
        cells.select { |cell| cell.status == "failed" }.map do |failed|
          blocked = cells.select { |cell| cell.blocked_by&.include?(failed.source) }.map(&:package).sort
          Blocker.new(source: failed.source, package: failed.package, blocked: blocked.freeze).freeze
        end.sort_by { |blocker| [-blocker.blocked.size, blocker.package] }.freeze
      end

      TOTALS = ["inherit", "build", "published", "system", "unavailable", "built", "kept", "failed", "skipped",
                "not built yet"].freeze

      def totals(cells)
        counts = Hash.new(0)
        cells.each do |cell|
          counts[cell.decision] += 1
          counts[cell.status] += 1 if cell.status && cell.status != "published"
        end
        TOTALS.to_h { |name| [name, counts[name]] }.freeze
      end

      def changes(target)
        return nil unless @diff

        found = @diff.targets.find { |one| one.target == target }
        (found ? found.changes : []).map do |change|
          Change.new(package: change.package, change: Diff::KINDS.fetch(change.kind, change.kind),
                     old: describe(change.old), new: describe(change.new)).freeze
        end.freeze
      end

      def describe(decision)
        return nil unless decision

        [decision.kind, decision.version, decision.from && "from #{decision.from}"].compact.join(" ")
      end
    end
  end
end
