# frozen_string_literal: true

require_relative "../error"
require_relative "../plan/lock_generator"

module Relspec
  module Publish
    # The release's lock as publish leaves it (docs/abi.md, "Early
    # cutoff"): a package the early cutoff kept is not uploaded, the
    # repository keeps its published build, and the lock records that
    # version and why; a candidate built after all moves its history only
    # now (compile leaves it, so that a kept one goes on from it). Read like
    # the LockedRelease it wraps (#lock, #inventory).
    class KeptBuilds
      # +locked+: LockedRelease; +results+: target => Builder::BuildResults
      # at the planned versions (nil: not built); +plans+: target =>
      # Builder::BuildPlan they were built from; +project+: the Project the
      # lock is written into.
      def initialize(locked, results, plans, project)
        @locked = locked
        @results = results
        @plans = plans
        @project = project
      end

      def lock
        @locked.lock
      end

      def inventory
        @locked.inventory
      end

      # Every kept record, [target, Builder::BuildResults::Record].
      def kept
        @results.flat_map { |target, read| read ? read.entries.select(&:kept?).map { |record| [target, record] } : [] }
      end

      # Refuses a keep whose version the release's repository does not hold
      # (any more): publishing around it would list a package nobody can
      # install. +own+ is called for the repository's contents
      # (Plan::OwnRepository) only when something was kept.
      def check
        found = kept
        return if found.empty?

        own = yield
        wrong = found.reject { |target, record| own.version_of(record.source, target).to_s == record.cutoff.keeps }
        return if wrong.empty?

        raise PublishError, wrong.map { |target, record|
          held = own.version_of(record.source, target)
          "#{target}: #{record.source} was kept at #{record.cutoff.keeps} by the early cutoff, but the repository " \
            "holds #{held || 'no version of it'}; build it: relspec build --rebuild-dependents"
        }.join("\n")
      end

      # Writes the lock with the outcomes published; returns a reader of
      # the new lock (the osdeps files name no versions: they stay).
      def record(effective)
        outcomes = @results.flat_map do |target, read|
          next [] unless read

          entries = @plans.fetch(target).entries.to_h { |entry| [entry.source, entry] }
          read.entries.select { |record| record.built? || record.kept? }.map do |record|
            kept = record.kept? ? record.cutoff : nil
            [target, record.package, record.version, kept, kept && kept_digest(entries, read, record.source)]
          end
        end
        lock = @locked.lock.published(outcomes)
        Plan::LockGenerator.write(@project.lock_path(effective.release), lock)
        Written.new(lock, @locked.inventory)
      end

      # The digest of the kept +source+'s debian/ that its history vouches
      # the kept version for: the plan's, made with its dependencies that
      # are candidates at the versions they keep, which holds when they
      # were all kept (one built after all names its new version: none,
      # and the next plan builds it again).
      def kept_digest(entries, read, source)
        entry = entries[source]
        return nil unless entry&.cutoff

        assumed = entry.build_depends.all? { |need| entries[need]&.cutoff.nil? || read[need]&.kept? }
        assumed ? entry.cutoff.debian_digest : nil
      end

      # The lock publish wrote, read as a LockedRelease.
      Written = Struct.new(:lock, :inventory)
    end
  end
end
