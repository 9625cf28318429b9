# frozen_string_literal: true

require_relative "../package_pattern"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # Blacklist entries must be able to match something, and should say why
      # they exist: a reviewer reads the reason in every rebuild they cause.
      module Blacklist
        def self.call(file)
          entries = file.usable("blacklist")
          return [] unless entries.is_a?(Array)

          seen = {}
          entries.each_with_index.flat_map do |entry, index|
            match, path = match_of(entry, index)
            next [] unless match.is_a?(String)

            problems = check_entry(file, entry, match, path)
            problems << duplicate(file, match, path, seen[match]) if seen[match]
            seen[match] ||= file.location(path).line
            problems
          end
        end

        def self.match_of(entry, index)
          entry.is_a?(Hash) ? [entry["match"], ["blacklist", index, "match"]] : [entry, ["blacklist", index]]
        end

        def self.check_entry(file, entry, match, path)
          problems = []
          parsed = PackagePattern.parse(match)
          problems << parsed.diagnostic(file.location(path)) if parsed.is_a?(PackagePattern::Invalid)
          if entry.is_a?(String)
            problems << Diagnostic.warning("blacklist-reason", "blacklist entry #{match.inspect} gives no reason",
                                           location: file.location(path),
                                           hint: "write { match: #{match.inspect}, reason: \"why it is rebuilt here\" }")
          end
          problems
        end

        def self.duplicate(file, match, path, first_line)
          Diagnostic.warning("duplicate-blacklist", "blacklist entry #{match.inspect} is listed twice",
                             location: file.location(path), hint: "it is already listed at line #{first_line}")
        end
      end
    end
  end
end
