# frozen_string_literal: true

require_relative "output_tree"
require_relative "builder/build_plan"
require_relative "builder/build_results"

module Relspec
  # A target's last build as the output tree holds it, read once and handed
  # to publish, report and abi, so that they all describe the same build:
  # its plan.yml (nil before compile) and the build records at the plan's
  # versions (nil before build). A record of an earlier version of a
  # planned package (a rebuild interrupted before it) is not the release's:
  # it counts as not built everywhere, as publish has always counted it.
  class TargetBuild
    attr_reader :target, :dir, :plan, :results

    # +tree+: the OutputTree; +target+: a Target.
    def self.read(tree, target)
      dir = tree.target_dir(target)
      path = tree.results_file(target)
      results = File.exist?(path) ? Builder::BuildResults.read(path, release: tree.release, target: target) : nil
      # results need their plan to be taken; a plan alone is read when present
      plan = results || File.exist?(tree.plan_file(target)) ? Builder::BuildPlan.read(dir) : nil
      results &&= results.at_versions(plan.entries.to_h { |entry| [entry.source, entry.version] })
      new(target: target, dir: dir, plan: plan, results: results)
    end

    def initialize(target:, dir:, plan:, results:)
      @target = target
      @dir = dir
      @plan = plan
      @results = results
      freeze
    end

    def built?
      !results.nil?
    end
  end
end
