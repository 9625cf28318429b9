# frozen_string_literal: true

require_relative "page"

module Relspec
  module Report
    # The critical path of a target's last build: the chain of
    # build-dependencies (plan.yml's order) whose build times add up to the
    # most. With enough jobs a build cannot end sooner than it; the page
    # shows which packages to make faster. Builds without a time (skipped,
    # not built) count zero. Ties go to the first source by name, so that the
    # same results give the same path.
    module CriticalPath
      module_function

      # +entries+: Builder::BuildPlan::Entry in dependency order;
      # +durations+: source => seconds. Returns [Step], first build first.
      def of(entries, durations)
        finish = {}
        via = {}
        entries.each do |entry|
          before = entry.build_depends.select { |need| finish.key?(need) }.max_by { |need| [finish[need], invert(need)] }
          via[entry.source] = before
          finish[entry.source] = (before ? finish[before] : 0) + durations.fetch(entry.source, 0)
        end
        # it ends with a build that took time (the skipped after a failure did not)
        last = finish.keys.select { |source| durations.key?(source) }.max_by { |source| [finish[source], invert(source)] }
        return [] if last.nil? || finish[last].zero?

        chain(last, via).map { |source| Step.new(source: source, duration: durations.fetch(source, 0)).freeze }
      end

      def chain(last, via)
        path = [last]
        path.unshift(via[path.first]) while via[path.first]
        path
      end

      # Sorts names descending inside max_by, so that the smallest name wins a tie.
      def invert(name)
        name.bytes.map(&:-@) + [0]
      end
    end
  end
end
