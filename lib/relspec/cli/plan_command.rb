# frozen_string_literal: true

require_relative "../plan"
require_relative "../plan/report"
require_relative "discarded_lock"
require_relative "../printable"

module Relspec
  module CLI
    # `relspec plan SPEC`: what the release inherits, builds and has already
    # published, and why. Writes the lock only with --write.
    class PlanCommand
      def initialize(path:, format:, write:, target:, timeout:, out:, err:, discard_lock: false)
        @discard_lock = discard_lock
        @path = path
        @format = format
        @write = write
        @target = target
        @timeout = timeout
        @out = out
        @err = err
      end

      def call
        result = Plan.run(@path, timeout: @timeout, discard_lock: @discard_lock)
        DiscardedLock.warn(result, @err)
        plan = result.plan
        targets = selected_targets(plan)
        report = Plan::Report.new(plan, result.lock, targets: targets)
        @out.write(render(report))
        write_lock(result) if @write
        0
      end

      private

      def selected_targets(plan)
        Target.select(@target, plan.targets.keys, plan.release)
      end

      def render(report)
        case @format
        when "json" then report.json
        when "markdown" then report.markdown
        else report.text
        end
      end

      def write_lock(result)
        changed = result.write_lock
        path = Printable.text(result.lock_path) # below the spec's folder, as the command line named it
        @err.puts(changed ? "wrote #{path}" : "#{path} is up to date")
      end
    end
  end
end
