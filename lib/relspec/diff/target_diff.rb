# frozen_string_literal: true

require_relative "package_change"
require_relative "revision_cause"

module Relspec
  module Diff
    # The decision diff of one target ("codename/arch"): +status+ is
    # "added", "removed" or "changed"/"unchanged"; +changes+ are the
    # PackageChanges sorted by kind then package; +rebuilt+ and
    # +rebuilt_before+ count the builds on each side.
    class TargetDiff
      attr_reader :target, :status, :changes, :rebuilt, :rebuilt_before

      # +old+, +new+: package => Decision (nil when the side lacks the
      # target); +commits+: a lambda (package) => CommitRange or nil.
      def self.compare(target, old, new, commits: ->(_) {})
        status = if old.nil? then "added"
                 elsif new.nil? then "removed"
                 end
        old ||= {}
        new ||= {}
        changes = (old.keys | new.keys).filter_map do |package|
          change_of(package, old[package], new[package], commits)
        end
        changes = with_revision_causes(changes)
        changes.sort_by! { |change| [KINDS.keys.index(change.kind), change.package] }
        status ||= changes.empty? ? "unchanged" : "changed"
        new(target, status, changes, new.values.count(&:built?), old.values.count(&:built?))
      end

      def self.change_of(package, old, new, commits)
        kind = kind_of(old, new)
        return nil unless kind

        range = old && new && old.version != new.version ? commits.call(package) : nil
        PackageChange.new(package: package, kind: kind, old: old, new: new, commits: range).freeze
      end

      # A revision bump is explained by the other changes of the target.
      def self.with_revision_causes(changes)
        by_package = changes.to_h { |change| [change.package, change] }
        changes.map do |change|
          cause = RevisionCause.of(change, by_package)
          cause ? change.with_rebuilt_because(cause) : change
        end
      end

      def self.kind_of(old, new)
        return "added" unless old
        return "removed" unless new
        return "inherit_to_build" if !old.built? && new.built?
        return "build_to_inherit" if old.built? && new.inherited?
        return "decision" if old.kind != new.kind && !(old.built? && new.built?)
        return "version" if old.version != new.version
        return "kept" if new.kept && old.kept != new.kept
        return "ancestor" if old.from != new.from || old.deb != new.deb
        return "cause" if old.causes != new.causes

        nil
      end

      def initialize(target, status, changes, rebuilt, rebuilt_before)
        @target = target
        @status = status
        @changes = changes.freeze
        @rebuilt = rebuilt
        @rebuilt_before = rebuilt_before
        freeze
      end

      def changed?
        status != "unchanged"
      end

      def count(kind)
        changes.count { |change| change.kind == kind }
      end

      def rebuilds
        changes.count(&:rebuild?)
      end

      # Packages whose osdeps entry changes: the Debian name a workspace
      # installs for them (own or inherited) is another, or there is none
      # on one side. [package, old deb, new deb]
      def osdeps
        changes.filter_map do |change|
          old = change.old&.kind == "unavailable" ? nil : change.old&.deb
          new = change.new&.kind == "unavailable" ? nil : change.new&.deb
          [change.package, old, new] unless old == new
        end
      end

      def counts
        { "rebuilt" => rebuilt, "rebuilt_before" => rebuilt_before, "rebuilds" => rebuilds,
          **KINDS.keys.to_h { |kind| [kind, count(kind)] } }
      end

      # "bionic/amd64: 14 rebuilt (+12), 2 added, 1 removed"
      def headline
        return "#{target}: target added, #{rebuilt} rebuilt" if status == "added"
        return "#{target}: target removed" if status == "removed"

        delta = rebuilt - rebuilt_before
        parts = ["#{rebuilt} rebuilt#{" (#{format('%+d', delta)})" unless delta.zero?}"]
        parts << "#{count('added')} added" << "#{count('removed')} removed"
        others = changes.size - count("added") - count("removed") - count("inherit_to_build") - count("build_to_inherit")
        parts << "#{others} other change#{'s' unless others == 1}" if others.positive?
        "#{target}: #{parts.join(', ')}"
      end

      def to_h
        { "target" => target, "status" => status, "headline" => headline, "counts" => counts,
          "changes" => changes.map(&:to_h),
          "osdeps" => osdeps.map { |package, old, new| { "package" => package, "old" => old, "new" => new }.compact } }
      end
    end
  end
end
