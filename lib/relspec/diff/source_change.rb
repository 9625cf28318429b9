# frozen_string_literal: true

require_relative "../printable"

module Relspec
  module Diff
    # A package whose recorded source (Plan::SourceRecord: URL, commit, …)
    # differs between the two sides in what the decision changes do not
    # already show: a pull request that points a package at another
    # repository, or at another commit with every decision kept, is a
    # change of the release even when no decision moved. +fields+: field =>
    # [old, new]; +decided+: whether a decision of the package changed too;
    # +recorded_in+: the out-of-date lock that records the new values where
    # the plan (old) has others, or nil.
    SourceChange = Struct.new(:package, :fields, :decided, :recorded_in, keyword_init: true) do
      # The SourceChange of +package+ from +before+ to +after+
      # (Plan::SourceRecord), or nil when nothing is left to say.
      def self.of(package, before, after, decided:, recorded_in: nil)
        fields = before.changes(after)
        fields = fields.slice(*SourceChange::UNSHOWN_BY_DECISIONS) if decided
        fields.empty? ? nil : new(package: package, fields: fields.freeze, decided: decided, recorded_in: recorded_in).freeze
      end

      # "base/types: source url https://a → https://b, commit 1111111 → 2222222 (no decision changed)"
      # "base/types: releases/r/lock.yml records url https://b, the plan https://a" for a lock edited by hand.
      def to_s
        if recorded_in
          recorded = fields.map { |field, (planned, written)| "#{field} #{shown(field, written)}, the plan #{shown(field, planned)}" }
          return "#{Printable.text(package)}: #{recorded_in} records #{recorded.join('; ')}"
        end
        moved = fields.map { |field, (old, new)| "#{field} #{shown(field, old)} → #{shown(field, new)}" }
        "#{Printable.text(package)}: source #{moved.join(', ')}#{' (no decision changed)' unless decided}"
      end

      def to_h
        { "package" => package, "fields" => fields.transform_values { |old, new| { "old" => old, "new" => new }.compact },
          "decisions_changed" => decided, "recorded_in" => recorded_in }.compact
      end

      private

      def shown(field, value)
        return "none" if value.nil?

        Printable.text(field == "commit" ? value[0, 12] : value)
      end
    end

    # When a decision of the package changed, it shows the version and the
    # commits (CommitRange), and the spec change the ref: what it never
    # shows is another repository.
    SourceChange::UNSHOWN_BY_DECISIONS = %w[url].freeze
  end
end
