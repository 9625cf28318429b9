# frozen_string_literal: true

require_relative "snapshot"
require_relative "target_diff"
require_relative "ancestor_change"
require_relative "spec_changes"
require_relative "commit_counter"
require_relative "source_change"

module Relspec
  module Diff
    # The diff of one release between two Snapshots: per target the
    # decision changes, the ancestors that changed, the spec keys that
    # changed linked to the decisions they caused, and the packages whose
    # recorded source moved in a way the decisions do not show (SourceChange).
    class ReleaseDiff
      attr_reader :old, :new, :targets, :ancestors, :spec_changes, :sources

      def self.compare(old, new, counter: CommitCounter.new(autoproj_root: new.workspace || old.workspace))
        commits = lambda do |package|
          before = old.packages[package]
          after = new.packages[package]
          next nil unless before&.commit && after&.commit && before.commit != after.commit

          CommitRange.new(from: before.commit, to: after.commit,
                          count: before.url == after.url ? counter.count(after.url, before.commit, after.commit) : nil).freeze
        end
        targets = (old.targets.keys | new.targets.keys).sort.map do |target|
          TargetDiff.compare(target, old.targets[target], new.targets[target], commits: commits)
        end
        new(old, new, targets, ancestor_changes(old, new, targets), SpecChanges.compare(old.spec, new.spec, targets),
            source_changes(old, new, targets))
      end

      # Every field of the records of the packages on both sides, and what
      # a side planned instead of its out-of-date lock found recorded
      # otherwise in that lock (Snapshot#edited: a lock edited by hand).
      def self.source_changes(old, new, targets)
        decided = targets.flat_map { |target| target.changes.map(&:package) }.uniq
        moved = (old.packages.keys & new.packages.keys).sort.filter_map do |package|
          SourceChange.of(package, old.packages[package], new.packages[package], decided: decided.include?(package))
        end
        moved + Array(old.edited) + Array(new.edited)
      end

      def self.ancestor_changes(old, new, targets)
        (old.ancestors.keys | new.ancestors.keys).sort.flat_map do |ancestor|
          before = old.ancestors.fetch(ancestor, {})
          after = new.ancestors.fetch(ancestor, {})
          (before.keys | after.keys).sort.filter_map do |codename|
            next if before[codename] == after[codename]

            change = if !before.key?(codename)
                       "added"
                     elsif !after.key?(codename)
                       "removed"
                     else
                       "changed"
                     end
            AncestorChange.new(ancestor: ancestor, codename: codename, change: change,
                               packages: followed(ancestor, codename, targets)).freeze
          end
        end
      end

      # Packages inherited from +ancestor+ on +codename+ (on either side) whose decision changed.
      def self.followed(ancestor, codename, targets)
        targets.select { |target| target.target.start_with?("#{codename}/") }.flat_map do |target|
          target.changes.select { |change| [change.old, change.new].compact.any? { |d| d.inherited? && d.from == ancestor } }
                .map(&:package)
        end.uniq.sort
      end

      def initialize(old, new, targets, ancestors, spec_changes, sources = [])
        @old = old
        @new = new
        @targets = targets.freeze
        @ancestors = ancestors.freeze
        @spec_changes = spec_changes.freeze
        @sources = sources.freeze
        freeze
      end

      def release
        new.release.empty? ? old.release : new.release
      end

      # "added", "removed", "renamed", "changed" or "unchanged".
      def status
        return "added" if old.targets.empty? && !new.targets.empty?
        return "removed" if new.targets.empty? && !old.targets.empty?
        return "renamed" if old.release != new.release && !old.release.empty?

        changed? ? "changed" : "unchanged"
      end

      def changed?
        targets.any?(&:changed?) || !ancestors.empty? || !spec_changes.empty? || !sources.empty? || old.release != new.release
      end

      def rebuilds
        targets.sum(&:rebuilds)
      end

      # Changes grouped by the cause that explains them (the end of the
      # chain, with the package it is about): [[cause text, [[target, package]]]],
      # largest group first. Only new builds (rebuilds) are grouped.
      def cause_groups
        groups = Hash.new { |hash, key| hash[key] = [] }
        targets.each do |target|
          target.changes.each do |change|
            next unless change.rebuild? && (change.rebuilt_because || !change.new.causes.empty?)

            # A new revision of the same source is there because of what
            # moved (a dependency's version), not because of why the
            # package is built at all.
            cause = change.rebuilt_because || plain_cause(change.new, change.package)
            groups[cause] << [target.target, change.package]
          end
        end
        groups.sort_by { |text, members| [-members.map(&:last).uniq.size, text] }
      end

      # "base/types is blacklisted by "base/types" (…)".
      def plain_cause(decision, package)
        root = decision.root_cause
        # Facts about targets and ancestors group all the packages they hit.
        return root if root.start_with?("no ancestor has target", "missing in all ancestors")

        "#{decision.root_package(package)} is #{root}"
      end

      # +stale_lock+ only when the side was planned because its lock was out of date.
      def side(snapshot)
        { "release" => snapshot.release, "source" => snapshot.source, "stale_lock" => snapshot.stale }.compact
      end

      def to_h
        { "release" => release, "status" => status,
          "old" => side(old), "new" => side(new),
          "rebuilds" => rebuilds, "spec_changes" => spec_changes.map(&:to_h), "ancestors" => ancestors.map(&:to_h),
          "targets" => targets.select(&:changed?).map(&:to_h) }.merge(sources.empty? ? {} : { "sources" => sources.map(&:to_h) })
      end
    end
  end
end
