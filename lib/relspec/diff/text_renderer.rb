# frozen_string_literal: true

require_relative "wording"

module Relspec
  module Diff
    # The diff for a terminal: per release the spec and ancestor changes,
    # then per target its headline and every change with its causes.
    # Colour only when asked (the CLI asks when writing to a terminal).
    class TextRenderer
      COLOURS = { bold: 1, red: 31, green: 32, yellow: 33, dim: 2 }.freeze
      KIND_COLOURS = { "added" => :green, "build_to_inherit" => :green, "removed" => :red,
                       "inherit_to_build" => :yellow }.freeze

      def initialize(color: false)
        @color = color
      end

      # Nothing at all when no release changed.
      def render(diffs)
        lines = diffs.select(&:changed?).flat_map { |diff| release(diff) }
        lines.empty? ? "" : "#{lines.join("\n")}\n"
      end

      private

      def release(diff)
        lines = [paint(:bold, "#{diff.release}: #{heading(diff)}")]
        diff.spec_changes.each do |change|
          lines << "  spec: #{change} → #{Wording.decisions(change.decisions)}"
        end
        diff.ancestors.each { |change| lines << "  #{change}" }
        diff.sources.each { |change| lines << "  #{change}" }
        diff.targets.select(&:changed?).each do |target|
          lines << "  #{paint(:bold, target.headline)}"
          width = target.changes.map { |change| KINDS.fetch(change.kind).size }.max
          target.changes.each do |change|
            label = KINDS.fetch(change.kind).ljust(width)
            lines << "    #{paint(KIND_COLOURS.fetch(change.kind, :dim), label)}  #{change.package}: #{Wording.change(change)}"
            why = Wording.causes(change)
            lines << "      #{why}" unless why.empty?
          end
          target.osdeps.each do |package, old, new|
            lines << "    osdeps #{package}: #{old || 'none'} → #{new || 'none'}"
          end
        end
        lines
      end

      def side(snapshot)
        snapshot.stale ? "#{snapshot.source} (planned: #{snapshot.stale} is out of date)" : snapshot.source
      end

      def heading(diff)
        old = side(diff.old)
        new = side(diff.new)
        sources = old == new ? new : "#{old} → #{new}"
        diff.status == "changed" ? sources : "#{diff.status} (#{sources})"
      end

      def paint(colour, text)
        @color ? "\e[#{COLOURS.fetch(colour)}m#{text}\e[0m" : text
      end
    end
  end
end
