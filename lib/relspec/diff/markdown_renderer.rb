# frozen_string_literal: true

require_relative "wording"

module Relspec
  module Diff
    # The diff as a pull request comment: per release a headline per target
    # with counts, the spec changes, the rebuilds grouped by cause in plain
    # words, then the details of each target folded in <details>. Details
    # that would make the comment longer than GitHub accepts are left out
    # with a note; the summary always stays.
    class MarkdownRenderer
      # GitHub refuses comments longer than this many characters.
      COMMENT_LIMIT = 65_536
      # Room kept for the truncation note.
      NOTE_ROOM = 400
      # Package names listed per cause group before "and N more".
      NAMES_PER_CAUSE = 30

      def initialize(limit: COMMENT_LIMIT)
        @limit = limit
      end

      # Nothing at all when no release changed.
      def render(diffs)
        changed = diffs.select(&:changed?)
        return "" if changed.empty?

        summary = changed.map { |diff| summary(diff) }.join("\n")
        details = changed.flat_map { |diff| details(diff) }
        "#{fit(summary, details)}\n"
      end

      private

      def summary(diff)
        lines = ["### #{diff.release}#{" (#{diff.status})" unless diff.status == 'changed'}", ""]
        lines << sides(diff) << "" if diff.old.stale || diff.new.stale
        diff.targets.select(&:changed?).each { |target| lines << "- **#{target.target}**: #{target.headline.split(': ', 2).last}" }
        lines << "- #{diff.rebuilds} new build#{'s' unless diff.rebuilds == 1} in all" if diff.targets.count(&:changed?) > 1
        unless diff.spec_changes.empty?
          lines << "" << "**Spec changes**" << ""
          diff.spec_changes.each { |change| lines << "- #{code_subject(change)}: #{Wording.decisions(change.decisions)}" }
        end
        causes = diff.cause_groups
        unless causes.empty?
          lines << "" << "**Why**" << ""
          causes.each { |text, members| lines << "- #{cause_line(text, members)}" }
        end
        lines.concat(listed("Ancestors", diff.ancestors)).concat(listed("Sources", diff.sources))
        lines << ""
        lines.join("\n")
      end

      # A bold heading and one item per change, or nothing without changes.
      def listed(heading, changes)
        return [] if changes.empty?

        ["", "**#{heading}**", ""] + changes.map { |change| "- #{escape(change.to_s)}" }
      end

      # Which side was planned (its lock out of date) and which was read.
      def sides(diff)
        [["old", diff.old], ["new", diff.new]].map do |name, side|
          next "#{name}: planned from `#{side.source}` (`#{side.stale}` is out of date: run `relspec plan --write`)" if side.stale

          "#{name}: read from `#{side.source}`"
        end.join("; ").then { |text| "_#{text.sub(/\Ao/, 'O')}_" }
      end

      def code_subject(change)
        text = escape(change.to_s)
        change.subject ? text.sub(escape(change.subject), "`#{change.subject}`") : text
      end

      # "3 rebuilt because base/types is blacklisted by …: `a`, `b` (bionic/amd64, buster/amd64)"
      def cause_line(text, members)
        packages = members.map(&:last).uniq.sort
        shown = packages.first(NAMES_PER_CAUSE).map { |name| "`#{name}`" }
        shown << "and #{packages.size - NAMES_PER_CAUSE} more" if packages.size > NAMES_PER_CAUSE
        "#{packages.size} rebuilt because #{escape(text)}: #{shown.join(', ')} (#{members.map(&:first).uniq.join(', ')})"
      end

      # One folded block per changed target: [opening, rows, closing].
      def details(diff)
        diff.targets.select(&:changed?).map do |target|
          opening = "<details><summary>#{diff.release} #{target.target}: #{target.changes.size} " \
                    "change#{'s' unless target.changes.size == 1}</summary>\n\n" \
                    "| package | change | old → new | why |\n| --- | --- | --- | --- |\n"
          rows = target.changes.map do |change|
            "| `#{change.package}` | #{KINDS.fetch(change.kind)} | #{escape(Wording.change(change))} | " \
              "#{escape(Wording.causes(change))} |\n"
          end
          unless target.osdeps.empty?
            rows << "\nosdeps entries:\n\n"
            target.osdeps.each { |package, old, new| rows << "- `#{package}`: #{old || 'none'} → #{new || 'none'}\n" }
          end
          [opening, rows, "\n</details>\n"]
        end
      end

      # The summary, then as many details (whole blocks, then rows) as fit
      # under the limit, then a note saying how much was left out.
      def fit(summary, details)
        text = +summary
        room = @limit - NOTE_ROOM
        details.each_with_index do |(opening, rows, closing), index|
          block = "\n#{opening}#{rows.join}#{closing}"
          if text.size + block.size <= room
            text << block
            next
          end
          shown = 0
          if text.size + opening.size + closing.size + 1 < room
            text << "\n" << opening
            rows.each do |row|
              break if text.size + row.size + closing.size >= room

              text << row
              shown += 1
            end
            text << closing
          end
          return "#{text}\n#{truncation_note(rows.size - shown, details.size - index - 1)}"
        end
        text.chomp
      end

      def truncation_note(rows, blocks)
        left = []
        left << "#{rows} row#{'s' unless rows == 1}" if rows.positive?
        left << "#{blocks} more target#{'s' unless blocks == 1}" if blocks.positive?
        "_Details left out (#{left.join(' and ')}): this comment would exceed #{@limit} characters. " \
          "`relspec diff --format text` shows everything._"
      end

      def escape(text)
        text.to_s.gsub("|", "\\|").gsub("<", "&lt;").gsub(">", "&gt;")
      end
    end
  end
end
