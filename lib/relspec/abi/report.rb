# frozen_string_literal: true

require "json"
require_relative "../rendered_formats"

module Relspec
  module Abi
    # What `relspec abi` found: per target, one Entry per library the release
    # builds, with the release it was compared against and the Verdict (nil
    # when no ancestor published a dump of it: "new"). Rendered as text,
    # markdown or JSON (docs/abi.md gives the JSON's shape).
    Report = Struct.new(:release, :targets, keyword_init: true)

    # Its rendering.
    class Report
      include RenderedFormats

      # +library+: the file name of the shared library.
      Entry = Struct.new(:package, :library, :against, :verdict, keyword_init: true) do
        def name
          verdict ? verdict.verdict : "new"
        end

        def to_h
          { "package" => package, "library" => library, "verdict" => name, "against" => against,
            "summary" => verdict&.summary || [], "changes" => verdict&.changes || [] }
        end
      end
      TargetReport = Struct.new(:target, :entries, keyword_init: true)

      # True when some library's verdict is +threshold+ or worse.
      def fails?(threshold)
        targets.any? { |one| one.entries.any? { |entry| entry.verdict&.at_least?(threshold) } }
      end

      def to_h
        { "release" => release,
          "targets" => targets.to_h { |one| [one.target.to_s, one.entries.map(&:to_h)] } }
      end

      private

      def text
        targets.map do |one|
          lines = ["#{release} #{one.target}: #{count(one.entries)}"]
          one.entries.each do |entry|
            lines << "  #{entry.library} (#{entry.package}): #{entry.name}#{" against #{entry.against}" if entry.against}"
            detail(entry).each { |line| lines << "    #{line}" }
          end
          "#{lines.join("\n")}\n"
        end.join
      end

      def markdown
        targets.map do |one|
          lines = ["### ABI of #{release} on #{one.target}", "", count(one.entries), ""]
          unless one.entries.empty?
            lines += ["| library | package | verdict | against |", "|---|---|---|---|"]
            one.entries.each do |entry|
              lines << "| `#{entry.library}` | #{entry.package} | **#{entry.name}** | #{entry.against || '-'} |"
            end
            one.entries.reject { |entry| detail(entry).empty? }.each do |entry|
              lines += ["", "<details><summary><code>#{entry.library}</code>: #{entry.name}</summary>", "", "```",
                        *detail(entry), "```", "</details>"]
            end
          end
          "#{lines.join("\n")}\n"
        end.join("\n")
      end

      # abidiff's summary and first changes, for what is not unchanged.
      def detail(entry)
        return [] if entry.verdict.nil? || entry.name == "unchanged"

        entry.verdict.summary + entry.verdict.changes
      end

      def count(entries)
        return "no shared library built" if entries.empty?

        tally = entries.map(&:name).tally
        "#{entries.size} #{entries.size == 1 ? 'library' : 'libraries'}: " +
          (Verdict::ORDER + ["new"]).filter_map { |name| "#{tally[name]} #{name}" if tally[name] }.join(", ")
      end
    end
  end
end
