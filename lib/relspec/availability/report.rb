# frozen_string_literal: true

require "json"
require_relative "../rendered_formats"

module Relspec
  module Availability
    # What a check found: per target, what answered and how many relations
    # were checked; every relation missing on a target with the packages
    # that need it and a hint. Rendered as text, Markdown or JSON; the order
    # is fixed (targets, then names) so equal inputs give equal bytes.
    class Report
      include RenderedFormats

      # +status+: :ok, :missing, :problem (the source failed: +reason+),
      # :unchecked (no source: +reason+), :partial (+unknown+ relations had
      # no answer, e.g. not in the Launchpad cache).
      TargetResult = Struct.new(:target, :source, :status, :checked, :missing, :unknown, :reason, keyword_init: true)
      Missing = Struct.new(:target, :name, :needed_by, :hint, keyword_init: true)

      attr_reader :release, :targets, :missing

      def initialize(release:, targets:, missing:)
        @release = release
        @targets = targets.sort_by { |result| result.target.to_s }.freeze
        @missing = missing.sort_by { |row| [row.target.to_s, row.name] }.freeze
        freeze
      end

      # Something is missing, or a source could not answer.
      def failed?
        !missing.empty? || targets.any? { |result| result.status == :problem }
      end

      # Targets that were not (fully) checked, without being an error.
      def unchecked
        targets.select { |result| %i[unchecked partial].include?(result.status) }
      end

      def to_h
        {
          "release" => release,
          "targets" => targets.map do |result|
            { "target" => result.target.to_s, "source" => result.source, "status" => result.status.to_s,
              "checked" => result.checked, "missing" => result.missing, "unknown" => result.unknown,
              "reason" => result.reason }.compact
          end,
          "missing" => missing.map do |row|
            { "target" => row.target.to_s, "name" => row.name, "needed_by" => row.needed_by, "hint" => row.hint }.compact
          end
        }
      end

      # One line per target, then the table of what is missing.
      def text
        lines = targets.map { |result| "#{result.target}: #{summary(result)}#{" (#{result.source})" if result.source}" }
        unless missing.empty?
          rows = [["target", "Debian name", "needed by", "hint"]] +
                 missing.map { |row| [row.target.to_s, row.name, row.needed_by.join(", "), row.hint ? "did you mean #{row.hint}?" : "-"] }
          widths = rows.transpose.map { |column| column.map(&:size).max }
          lines << "" << "missing OS dependencies:"
          lines.concat(rows.map { |row| row.each_with_index.map { |cell, i| cell.ljust(widths[i]) }.join("  ").rstrip })
        end
        "#{lines.join("\n")}\n"
      end

      def markdown
        lines = ["## OS dependencies of #{release}", "", "| target | source | result |", "| --- | --- | --- |"]
        lines.concat(targets.map { |result| "| #{result.target} | #{result.source || '-'} | #{escape(summary(result))} |" })
        unless missing.empty?
          lines << "" << "| target | Debian name | needed by | hint |" << "| --- | --- | --- | --- |"
          lines.concat(missing.map do |row|
            "| #{row.target} | `#{escape(row.name)}` | #{escape(row.needed_by.join(', '))} | " \
              "#{row.hint ? "`#{escape(row.hint)}`" : '-'} |"
          end)
        end
        "#{lines.join("\n")}\n"
      end

      private

      def summary(result)
        case result.status
        when :unchecked then "not checked: #{result.reason}"
        when :problem then "could not be checked: #{result.reason}"
        else
          text = "#{result.checked} relations checked"
          text += ", #{result.missing} missing" if result.missing.positive?
          text += ", #{result.unknown} without an answer (#{result.reason})" if result.unknown.positive?
          text
        end
      end

      def escape(text)
        text.gsub("|", "\\|")
      end
    end
  end
end
