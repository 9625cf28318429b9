# frozen_string_literal: true

require_relative "../plan"
require_relative "../project"
require_relative "../diff/lock_check"

module Relspec
  module CLI
    # `relspec plan --check [SPEC…]`: the CI gate for committed release
    # state (Diff::LockCheck), for every spec named or all of specs/. Writes
    # nothing. Returns 1 when any lock is out of date.
    class PlanCheckCommand
      def initialize(paths:, timeout:, out:)
        @paths = paths
        @timeout = timeout
        @out = out
      end

      def call
        paths = Diff::LockCheck.spec_paths(@paths, Project.new("."))
        stale = paths.reject { |path| current?(Diff::LockCheck.verdict(Plan.run(path, timeout: @timeout))) }
        return 0 if stale.empty?

        @out.puts("#{stale.size} lock#{'s' unless stale.size == 1} out of date: run `relspec compile SPEC` " \
                  "(or `relspec plan --write SPEC`) and commit releases/")
        1
      end

      private

      def current?(verdict)
        return true if verdict.current?

        if verdict.status == :missing
          @out.puts("#{verdict.path}: missing")
          return false
        end
        @out.puts("#{verdict.path}: out of date")
        verdict.reasons.each { |reason| @out.puts("  #{reason}") }
        @out.write(verdict.diff)
        false
      end
    end
  end
end
