# frozen_string_literal: true

require "digest"
require "json"
require_relative "history"
require_relative "../project"
require_relative "cause"
require_relative "decision"
require_relative "source_record"
require_relative "../frozen"
require_relative "../debian/package_version"

module Relspec
  module Plan
    # releases/<release>/lock.yml (docs/plan.md, The lock file) as a value: what a plan
    # decided, what it read to decide it, and the history of every build the
    # release has made. LockGenerator writes it and LockParser reads it back,
    # each the mirror of the other (as Bundler's LockfileGenerator and
    # LockfileParser).
    class Lock
      FORMAT_KEY = "relspec_lock"
      FORMAT_VERSION = 2

      # One recorded decision: +decision+ is "inherit", "build", "published",
      # "system" or "unavailable"; +version+ a string as written; +causes+
      # the cause chain, one line per step (a plan gives the Cause itself,
      # spelled out when read: the chains of a deep graph add up to the
      # square of its depth, which only a written lock pays); +depends+
      # (builds; nil in locks written before it was recorded): Decision#depends.
      # Its fields, in the order the lock writes them (LockParser accepts
      # exactly these): the one place that defines them.
      class Entry
        FIELDS = %w[decision deb version from causes depends debian_digest kept].freeze
        # The decisions a lock records; all but "unavailable" have a version.
        DECISIONS = %w[inherit build published system unavailable].freeze

        attr_reader :decision, :deb, :version, :from, :depends, :debian_digest, :kept

        # +kept+: why the early cutoff kept the published +version+ (docs/abi.md).
        def initialize(decision:, deb: nil, version: nil, from: nil, causes: nil, depends: nil, debian_digest: nil, kept: nil)
          @decision = Frozen.deep(decision)
          @deb = Frozen.deep(deb)
          @version = Frozen.deep(version)
          @from = Frozen.deep(from)
          @causes = causes.is_a?(Cause) ? causes : Frozen.deep(causes)
          @depends = Frozen.deep(depends)
          @debian_digest = Frozen.deep(debian_digest)
          @kept = Frozen.deep(kept)
          freeze
        end

        def causes
          @causes.is_a?(Cause) ? @causes.chain : @causes
        end

        def to_h
          FIELDS.to_h { |field| [field, public_send(field)] }.compact
        end

        # The Decision this entry records for +package+ (its version as
        # written), for the osdeps files.
        def to_decision(package)
          Decision.new(package: package, kind: decision.to_sym, deb_name: deb, version: version, ancestor: from,
                       kept: kept).freeze
        end
      end

      attr_reader :release, :spec_digest, :ancestors, :packages, :targets, :history, :warnings, :notes

      # +ancestors+: name => codename => digest; +packages+: name =>
      # SourceRecord (or its mapping); +targets+: "codename/arch" => package
      # => Entry; +history+: History. Everything is kept deep-frozen.
      def initialize(release:, spec_digest:, ancestors:, packages:, targets:, history:, warnings:, notes:)
        @release = Frozen.deep(release)
        @spec_digest = Frozen.deep(spec_digest)
        @ancestors = Frozen.deep(ancestors)
        @packages = packages.to_h { |name, record| [Frozen.deep(name), SourceRecord.from(record)] }.freeze
        @targets = targets.to_h { |target, entries| [Frozen.deep(target), entries.to_h { |name, entry| [Frozen.deep(name), entry] }.freeze] }.freeze
        @history = history
        @warnings = Frozen.deep(warnings)
        @notes = Frozen.deep(notes)
        freeze
      end

      # The lock of +plan+ (a ReleasePlan with settled versions), whose
      # history is +history+ (the previous lock's) with this plan's builds.
      def self.from_plan(plan, spec_digest, history)
        targets = plan.targets.sort_by { |target, _| target.to_s }.to_h do |target, decisions|
          entries = decisions.transform_values { |decision| entry_of(decision) }
          plan.unavailable.fetch(target).each do |name, cause|
            entries[name] = Entry.new(decision: "unavailable", causes: cause).freeze
          end
          [target.to_s, entries.sort.to_h.freeze]
        end
        new(release: plan.release, spec_digest: spec_digest, ancestors: ancestors_of(plan),
            packages: plan.packages.sort.to_h, targets: targets, history: history_with(history, plan),
            warnings: plan.warnings.map(&:message), notes: plan.notes)
      end

      def self.entry_of(decision)
        Entry.new(decision: decision.kind.to_s, deb: decision.deb_name, version: decision.version&.to_s,
                  from: decision.ancestor, causes: decision.cause, depends: decision.depends,
                  debian_digest: decision.debian_digest, kept: decision.kept).freeze
      end

      # An early cutoff candidate's history does not move here: the
      # revision it keeps, if kept, is the one recorded; publish records
      # the outcome (#published).
      def self.history_with(history, plan)
        history.with_all(plan.targets.flat_map do |target, decisions|
          decisions.values.select { |decision| (decision.build? && !decision.cutoff) || decision.published? }.map do |decision|
            [target, decision.package, decision.version, decision.debian_digest, decision.kept]
          end
        end)
      end

      def self.ancestors_of(plan)
        plan.release_digests.keys.map(&:first).uniq.sort.to_h do |name|
          digests = plan.release_digests.select { |(ancestor, _), _| ancestor == name }
          [name, digests.map { |(_, codename), digest| [codename, digest] }.sort.to_h]
        end
      end
      private_class_method :entry_of, :history_with, :ancestors_of

      def self.path(root, release)
        Project.new(root).lock_path(release)
      end

      # The digest of what the spec means (its effective values), so a lock
      # records which spec it was planned from.
      def self.spec_digest(effective)
        Digest::SHA256.hexdigest(JSON.generate(effective.to_h))
      end

      # This lock once publish has put each of +outcomes+ into the
      # release's repository ([target, package, version, kept, kept
      # digest]: the version built; kept the early cutoff's Cutoff when it
      # kept the published version instead, else nil; for a keep, the digest
      # of the debian/ its history now vouches the kept version for, nil
      # when none is known): the builds' history moves to them (a
      # candidate's did not at compile time), and a kept package's decision
      # becomes "published" at the version kept (docs/abi.md). Outcomes of
      # another version than the locked build are left alone.
      def published(outcomes)
        entries = targets.transform_values(&:dup)
        builds = outcomes.filter_map do |target, package, built, kept, kept_digest|
          entry = entries.dig(target.to_s, package)
          next unless entry&.decision == "build" && entry.version == built

          version = Debian::PackageVersion.parse(kept ? kept.keeps : entry.version)
          if kept
            entries[target.to_s][package] = Entry.new(decision: "published", deb: entry.deb, version: version.to_s,
                                                      from: entry.from, causes: entry.causes, depends: entry.depends,
                                                      debian_digest: kept_digest || entry.debian_digest, kept: kept.summary).freeze
          end
          next if kept && !kept_digest # its next plan builds it again: safe

          [target, package, version, kept ? kept_digest : entry.debian_digest, kept&.summary]
        end
        Lock.new(release: release, spec_digest: spec_digest, ancestors: ancestors, packages: packages, targets: entries,
                 history: history.with_all(builds), warnings: warnings, notes: notes)
      end

      # Plain data, in the order the file is written.
      def to_h
        {
          FORMAT_KEY => FORMAT_VERSION, "release" => release, "spec_digest" => spec_digest, "ancestors" => ancestors,
          "packages" => packages.transform_values(&:to_h),
          "targets" => targets.transform_values { |entries| entries.transform_values(&:to_h) },
          "history" => history.to_h, "warnings" => warnings, "notes" => notes
        }
      end
    end
  end
end
