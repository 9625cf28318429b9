# frozen_string_literal: true

require_relative "requirements"
require_relative "report"

module Relspec
  module Availability
    # The availability check (`relspec check`, and compile before it
    # emits): every OS relation of every package the release builds must
    # resolve on every target — directly, through Provides, or as an
    # Architecture: all package. Each source is asked once for all the
    # names of all its targets (so Launchpad can share one pool of
    # questions), then each relation is judged: found when any alternative
    # exists, missing when none does, unknown when some had no answer.
    class Check
      def self.run(release, requirements, sources)
        new(release, requirements, sources).run
      end

      def initialize(release, requirements, sources)
        @release = release
        @requirements = requirements
        @sources = sources
      end

      def run
        results = []
        missing = []
        by_source = {}
        @requirements.by_target.each_key do |target|
          source, reason = @sources.for(target)
          if source
            (by_source[source] ||= []) << target
          else
            results << Report::TargetResult.new(target: target, status: :unchecked, reason: reason)
          end
        end
        by_source.each do |source, targets|
          answers = source.lookup_many(targets.to_h { |target| [target, @requirements.names(target)] })
          targets.each do |target|
            found, problem = answers.fetch(target)
            results << judge(source, target, found, problem, missing)
          end
        end
        Report.new(release: @release, targets: results, missing: missing)
      end

      private

      def judge(source, target, found, problem, missing)
        if problem
          return Report::TargetResult.new(target: target, source: source.describe, status: :problem, reason: problem)
        end

        relations = @requirements.by_target.fetch(target)
        unknown = 0
        relations.each do |relation|
          answers = relation.names.map { |name| found[name] }
          next if answers.include?(true)

          if answers.include?(nil)
            unknown += 1
          else
            missing << Report::Missing.new(target: target, name: relation.text, needed_by: relation.needed_by,
                                           hint: source.hint(target, relation.names.first))
          end
        end
        lacking = missing.count { |row| row.target == target }
        Report::TargetResult.new(target: target, source: source.describe, checked: relations.size, missing: lacking,
                                 unknown: unknown, status: status(lacking, unknown),
                                 reason: unknown.positive? ? "not in the cache; run relspec check" : nil)
      end

      def status(lacking, unknown)
        return :missing if lacking.positive?

        unknown.positive? ? :partial : :ok
      end
    end
  end
end
