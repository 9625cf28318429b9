# frozen_string_literal: true

require "json"
require_relative "../rendered_formats"

module Relspec
  module Mirror
    # What `relspec mirror` and `relspec mirror verify` found, per target:
    # rendered as text for the terminal, as VERIFIED.md beside the mirror
    # and as JSON. Only facts of the mirror go in (no times, no paths of the
    # machine that made it): the same mirror gives the same bytes.
    class Report
      include RenderedFormats

      # +counts+: Hash of what the closure holds; +changes+: added/removed
      # (nil for verify); +missing+: lines; +checks+: Proof::Check;
      # +pinned+: lines, the release's packages kept over the distribution's
      # higher versions (nil for verify: the mirror holds one version only).
      TargetReport = Struct.new(:target, :counts, :changes, :missing, :checks, :pinned, keyword_init: true) do
        def complete?
          missing.empty? && checks.none? { |check| check.status == "failed" } &&
            checks.any? { |check| check.name == "static" && check.passed? }
        end
      end

      attr_reader :release, :targets, :files

      # +files+: the Proof::Check of the mirror's files (Integrity), which
      # `relspec mirror verify` makes; nil when not checked.
      def initialize(release, targets, files: nil)
        @release = release
        @targets = targets.freeze
        @files = files
        freeze
      end

      def complete?
        targets.all? { |one| complete_target?(one) }
      end

      def to_h
        { "release" => release, "complete" => complete?,
          "targets" => targets.to_h do |one|
            [one.target.to_s, { "complete" => complete_target?(one), "packages" => one.counts, "changes" => one.changes,
                                "missing" => one.missing, "pinned" => one.pinned, "checks" => one.checks.to_h { |check| check_h(check) } }]
          end, "files" => files && check_h(files)[1] }
      end

      def text
        lines = targets.flat_map do |one|
          head = ["#{one.target}: #{complete_target?(one) ? 'complete' : 'NOT complete'} — #{summary(one.counts)}"]
          head << "  changes: #{change_text(one.changes)}" if one.changes
          head.concat(Array(one.pinned).map { |line| "  pinned: #{line}" })
          head + one.missing.map { |line| "  missing: #{line}" } +
            one.checks.flat_map do |check|
              ["  #{check.name} proof: #{check.status} (#{check.detail})", *check.problems.map { |line| "    #{line}" }]
            end
        end
        lines += ["files: #{files.status} (#{files.detail})", *files.problems.map { |line| "  #{line}" }] if files
        "#{lines.join("\n")}\n"
      end

      def markdown
        body = targets.map do |one|
          checks = one.checks.map do |check|
            "- #{check.name} proof: **#{check.status}** (#{check.detail})" +
              check.problems.map { |line| "\n  - #{line}" }.join
          end
          missing = one.missing.map { |line| "- missing: #{line}" }
          pinned = Array(one.pinned).map { |line| "- pinned: #{line}" }
          ["## #{one.target}: #{complete_target?(one) ? 'complete' : 'NOT complete'}", "", "#{summary(one.counts)}.", "",
           *pinned, *missing, *checks].join("\n")
        end
        body << ["## Files: **#{files.status}** (#{files.detail})", *files.problems.map { |line| "- #{line}" }].join("\n") if files
        "# Mirror of #{release}\n\nMade and checked by `relspec mirror`; `relspec mirror verify DIR` checks it " \
          "again offline (docs/mirror.md).\n\n#{body.join("\n\n")}\n"
      end

      private

      # A target of a mirror whose files are not what its indices say is
      # not complete, whatever its proofs found.
      def complete_target?(one)
        one.complete? && files&.status != "failed"
      end

      def check_h(check)
        [check.name, { "status" => check.status, "detail" => check.detail, "problems" => check.problems }]
      end

      # "351 packages (7 of the release, 4 of them inherited; 344 from the
      # distribution, 33 of them its minimal system), 252.5 MB": the parts
      # that +counts+ has (verify knows no origins).
      def summary(counts)
        release = "#{counts['release']} of the release"
        release += ", #{counts['inherited']} of them inherited from its ancestors" if counts["inherited"]
        parts = [release]
        parts << "#{counts['distribution']} from the distribution" if counts["distribution"]
        parts << "#{counts['required']} for the minimal system"
        "#{counts['total']} packages (#{parts.join('; ')}), #{megabytes(counts['bytes'])}"
      end

      def change_text(changes)
        "#{changes['added']} added (#{megabytes(changes['added_bytes'])}), #{changes['removed']} removed, " \
          "#{changes['kept']} kept"
      end

      def megabytes(bytes)
        format("%.1f MB", bytes.to_i / 1_000_000.0)
      end
    end
  end
end
