# frozen_string_literal: true

require_relative "../package_pattern"
require_relative "../names"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # `leave_out` entries are written like blacklist matches (name, glob,
      # /regex/); `targets` names distribution codenames. Whether those are
      # targets of the release depends on inherited `targets`: HierarchyRules.
      module LeaveOut
        def self.call(file)
          entries = file.usable("leave_out")
          return [] unless entries.is_a?(Array)

          seen = {}
          entries.each_with_index.flat_map do |entry, index|
            next [] unless entry.is_a?(Hash) && entry["match"].is_a?(String)

            problems = pattern_problems(file, entry["match"], ["leave_out", index, "match"])
            problems.concat(codename_problems(file, entry["targets"], ["leave_out", index, "targets"]))
            key = [entry["match"], entry["targets"]]
            if seen[key]
              problems << Diagnostic.warning("duplicate-leave-out", "leave_out entry #{entry['match'].inspect} is listed twice",
                                             location: file.location(["leave_out", index]), hint: "it is already listed at line #{seen[key]}")
            end
            seen[key] ||= file.location(["leave_out", index]).line
            problems
          end
        end

        def self.pattern_problems(file, match, path)
          parsed = PackagePattern.parse(match)
          return [] unless parsed.is_a?(PackagePattern::Invalid)

          [parsed.diagnostic(file.location(path), rule: parsed.rule.sub("blacklist", "leave-out"))]
        end

        def self.codename_problems(file, codenames, path)
          return [] unless codenames.is_a?(Array)
          # `targets: []` would validate and leave nothing out, silently
          if codenames.empty?
            return [Diagnostic.error("leave-out-target", "the leave_out entry names no target: it would leave nothing out",
                                     location: file.location(path),
                                     hint: "name the codenames it applies to, or remove `targets` to leave it out on every target")]
          end

          codenames.each_with_index.filter_map do |codename, index|
            next if Names::CODENAME.match?(codename)

            Diagnostic.error("leave-out-target", "#{codename.inspect} is not a distribution codename",
                             location: file.location(path + [index]), hint: "write the codename of a target, e.g. bookworm")
          end
        end
      end
    end
  end
end
