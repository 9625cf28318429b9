# frozen_string_literal: true

module Relspec
  module Abi
    # What libabigail's `abidiff` says about two dumps of one library, as one
    # of four verdicts (docs/abi.md):
    #
    # - unchanged: exit status 0, nothing to report;
    # - compatible: an ABI change (status bit 4) whose summaries count only
    #   additions (nothing removed, nothing changed);
    # - changed: an ABI change that needs review (a function or variable
    #   whose type changed underneath: "indirect sub-type change");
    # - incompatible: abidiff's own "incompatible" bit (8): removed functions
    #   or variables, changed virtual tables and the like.
    #
    # +summary+: abidiff's summary lines; +changes+: the first lines of its
    # report after them.
    Verdict = Struct.new(:verdict, :summary, :changes, keyword_init: true)

    # The verdict's rules.
    class Verdict
      ORDER = %w[unchanged compatible changed incompatible].freeze
      ABI_CHANGE = 4
      INCOMPATIBLE = 8
      SUMMARY = /changes summary:/
      # "0 Removed, 1 Changed (2 filtered out), 3 Added functions"
      COUNT = /(\d+) (Removed|Changed)\b/
      CHANGE_LINES = 12

      # The verdict of abidiff's +status+ (its exit status, without its
      # error bits) and +report+ (its standard output).
      def self.of(status, report)
        lines = report.lines.map(&:rstrip)
        summary = lines.grep(SUMMARY)
        changes = lines.drop_while { |line| !line.match?(SUMMARY) }.drop(summary.size).reject(&:empty?)
        new(verdict: name(status, summary), summary: summary, changes: changes.first(CHANGE_LINES).freeze).freeze
      end

      def self.name(status, summary)
        return "incompatible" if status.anybits?(INCOMPATIBLE)
        return "unchanged" unless status.anybits?(ABI_CHANGE)

        removed_or_changed = summary.sum { |line| line.scan(COUNT).sum { |count, _| count.to_i } }
        removed_or_changed.zero? ? "compatible" : "changed"
      end

      # True when this verdict is +threshold+ (a verdict name) or worse.
      def at_least?(threshold)
        ORDER.index(verdict) >= ORDER.index(threshold)
      end
    end
  end
end
