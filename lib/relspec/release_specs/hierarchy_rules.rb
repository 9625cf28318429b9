# frozen_string_literal: true

require_relative "../diagnostic"
require_relative "../suggestion"
require_relative "names"

module Relspec
  module ReleaseSpec
    # Checks that need the effective spec: whether a release has targets at
    # all, whether each target codename is a known distribution once
    # inherited `distributions:` are taken into account, and whether
    # `leave_out` names only target codenames.
    module HierarchyRules
      # +lineage_complete+ is false when a parent could not be resolved: then
      # a missing value may well be in the parent nobody could read.
      def self.call(effective, broken, root_file, lineage_complete:)
        [*missing_targets(effective, broken, root_file, lineage_complete), *unknown_distributions(effective, broken),
         *leave_out_targets(effective, broken)]
      end

      # A `leave_out` entry for a codename the release does not target would
      # never leave anything out.
      def self.leave_out_targets(effective, broken)
        return [] if broken.include?("leave_out") || broken.include?("targets") || !effective.values.key?("targets")

        origin = effective.origin("leave_out")
        return [] unless origin

        effective.leave_out_codenames.each_with_index.flat_map do |codenames, index|
          codenames.each_with_index.filter_map do |codename, position|
            # a name that is no codename at all is the file rule's error
            next if effective.targets.key?(codename) || !Names::CODENAME.match?(codename.to_s)

            Diagnostic.error("leave-out-target", "leave_out names #{codename.inspect}, which is not a target of the release",
                             location: origin.file.location(origin.path + [index, "targets", position]),
                             hint: Suggestion.hint(codename, effective.targets.keys) || "targets: #{effective.targets.keys.sort.join(', ')}")
          end
        end
      end

      def self.missing_targets(effective, broken, root_file, lineage_complete)
        return [] if effective.values.key?("targets") || broken.include?("targets") || broken.include?("parent")
        return [] unless lineage_complete

        [Diagnostic.error("missing-targets",
                          "release #{(effective.release || root_file.file_release).inspect} has no targets " \
                          "and no ancestor defines them",
                          location: root_file.location(root_file.key?("release") ? ["release"] : []),
                          hint: "add `targets:` mapping codenames to architectures, e.g. { bionic: [amd64] }")]
      end

      def self.unknown_distributions(effective, broken)
        return [] if broken.include?("distributions") || !effective.values.key?("targets")

        known = effective.distributions
        origin = effective.origin("targets")
        effective.targets.keys.reject { |codename| known.key?(codename) }.map do |codename|
          Diagnostic.error("unknown-distribution", "unknown distribution #{codename.inspect}",
                           location: origin.file.key_location(origin.path + [codename]),
                           hint: Suggestion.hint(codename, known.keys) ||
                                 "define it under `distributions:` with its type and labels")
        end
      end
    end
  end
end
