# frozen_string_literal: true

require_relative "../plan"

module Relspec
  module CLI
    # `relspec why SPEC PACKAGE`: one package's decision on each target, with
    # its whole cause chain.
    class WhyCommand
      def initialize(path:, package:, target:, timeout:, out:)
        @path = path
        @package = package
        @target = target
        @timeout = timeout
        @out = out
      end

      def call
        plan = Plan.run(@path, timeout: @timeout).plan
        targets = Target.select(@target, plan.targets.keys.sort_by(&:to_s), plan.release)
        unless plan.packages.key?(@package)
          hint = Suggestion.hint(@package, plan.packages.keys)
          raise Error, "#{@package} is not part of release #{plan.release}#{" (#{hint})" if hint}"
        end

        targets.each do |target|
          gap = plan.unavailable.fetch(target)[@package]
          @out.write(gap ? explain_gap(target, gap) : explain(target, plan.targets.fetch(target)[@package]))
        end
        0
      end

      private

      def explain_gap(target, cause)
        "#{target}: #{@package} cannot be built there, because:\n#{steps(cause)}\n"
      end

      def steps(cause)
        Plan::Cause.steps(cause.chain).join("\n")
      end

      def explain(target, decision)
        return "#{target}: #{@package} is not selected there\n" unless decision

        case decision.kind
        when :inherit
          "#{target}: #{@package} is inherited from #{decision.ancestor} as #{decision.deb_name} #{decision.version}\n"
        when :system
          "#{target}: #{@package} is taken from the distribution as #{decision.deb_name} #{decision.version}\n"
        when ->(_) { decision.kept }
          # the early cutoff kept it when its dependencies were rebuilt (docs/abi.md)
          "#{target}: #{@package} is kept at #{decision.version} as #{decision.deb_name}: #{decision.kept}\n"
        else
          verb = decision.published? ? "was built here and is published" : "is built here"
          "#{target}: #{@package} #{verb} as #{decision.deb_name} #{decision.version}, because:\n#{steps(decision.cause)}\n" \
            "#{"  #{decision.cutoff}\n" if decision.cutoff}"
        end
      end
    end
  end
end
