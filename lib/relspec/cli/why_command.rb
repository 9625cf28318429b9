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
        plan = Plan.compute(@path, timeout: @timeout).plan
        targets = plan.targets.keys.sort_by(&:to_s)
        targets = targets.select { |target| target.to_s == @target } if @target
        raise Error, "#{@target} is not a target of #{plan.release}" if targets.empty?
        unless plan.packages.key?(@package)
          hint = Suggestion.hint(@package, plan.packages.keys)
          raise Error, "#{@package} is not part of release #{plan.release}#{" (#{hint})" if hint}"
        end

        targets.each { |target| @out.write(explain(target, plan.targets.fetch(target)[@package])) }
        0
      end

      private

      def explain(target, decision)
        return "#{target}: #{@package} is not selected there\n" unless decision

        case decision.kind
        when :inherit
          "#{target}: #{@package} is inherited from #{decision.ancestor} as #{decision.deb_name} #{decision.version}\n"
        else
          verb = decision.published? ? "was built here and is published" : "is built here"
          chain = decision.cause.chain.each_with_index.map { |step, depth| "#{'  ' * (depth + 1)}#{'└ ' if depth.positive?}#{step}" }
          "#{target}: #{@package} #{verb} as #{decision.deb_name} #{decision.version}, because:\n#{chain.join("\n")}\n"
        end
      end
    end
  end
end
