# frozen_string_literal: true

require_relative "snapshot"
require_relative "../plan/lock_parser"
require_relative "../printable"

module Relspec
  module Diff
    # The one place where the diff reads a lock: a Plan::Lock (read strictly
    # by Plan::LockParser, or computed by a plan) becomes the diff's own
    # Snapshot. When the lock changes, only this file follows it.
    module LockView
      module_function

      # A lock file's text (+source+ names it in messages) as a Snapshot; a
      # lock relspec cannot read is a LockError naming file:line.
      def parse(text, source:)
        snapshot(Plan::LockParser.parse(text, file: source, release: nil), source: source)
      end

      # +lock+: a Plan::Lock (deep-frozen: its records are shared); +source+:
      # where it was read.
      def snapshot(lock, source:)
        Snapshot.new(release: lock.release, source: source, spec_digest: lock.spec_digest,
                     ancestors: lock.ancestors,
                     packages: lock.packages,
                     targets: lock.targets.transform_values { |entries| decisions(entries) }.freeze,
                     spec: nil).freeze
      end

      # A lock file is untrusted text: the causes the diff prints are kept
      # Printable (a plan's own already are, so both sides compare alike).
      def decisions(entries)
        entries.transform_values do |entry|
          Decision.new(kind: entry.decision, deb: entry.deb, version: entry.version, from: entry.from,
                       causes: Array(entry.causes).map { |line| Printable.text(line) }.freeze, depends: entry.depends,
                       kept: entry.kept && Printable.text(entry.kept)).freeze
        end.freeze
      end
    end
  end
end
