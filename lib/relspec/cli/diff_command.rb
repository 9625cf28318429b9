# frozen_string_literal: true

require_relative "../diff"
require_relative "../display_path"

module Relspec
  module CLI
    # `relspec diff OLD NEW` and `relspec diff --base REF [SPEC…]`: the
    # release diff for review. Returns 1 when --exit-code is given and
    # something differs, or when more packages are rebuilt than
    # --fail-on-rebuilds allows; 0 otherwise.
    class DiffCommand
      # Compares the project in the current folder when --base names no spec.
      PROJECT_ROOT = "."

      def initialize(paths:, base:, format:, exit_code:, fail_on_rebuilds:, timeout:, out:, err:, color: false)
        @paths = paths
        @base = base
        @format = format
        @exit_code = exit_code
        @fail_on_rebuilds = fail_on_rebuilds
        @timeout = timeout
        @out = out
        @err = err
        @color = color
      end

      def call
        if @fail_on_rebuilds&.negative?
          raise InvalidOption, "--fail-on-rebuilds must be 0 or more, not #{@fail_on_rebuilds}"
        end

        diffs = pairs.map { |old, new| Diff::ReleaseDiff.compare(old, new) }
        @out.write(Diff.render(diffs, @format, color: @color))
        rebuilds = diffs.sum(&:rebuilds)
        if @fail_on_rebuilds && rebuilds > @fail_on_rebuilds
          @err.puts("relspec diff: #{rebuilds} rebuilds, more than the #{@fail_on_rebuilds} allowed (--fail-on-rebuilds)")
          return 1
        end
        @exit_code && diffs.any?(&:changed?) ? 1 : 0
      end

      private

      def pairs
        return base_pairs if @base
        raise Error, "relspec diff needs OLD and NEW (lock files, release folders or specs), or --base REF" unless @paths.size == 2

        [@paths.map { |path| Diff::Input.snapshot(path, planner: planner) }]
      end

      def base_pairs
        roots = @paths.map { |path| DisplayPath.of(File.dirname(File.expand_path(path), 2)) }.uniq
        raise Error, "the specs given belong to different projects: #{roots.join(', ')}" if roots.size > 1

        names = @paths.empty? ? nil : @paths.map { |path| File.basename(path, ".yml") }
        Diff::BaseComparison.new(roots.first || PROJECT_ROOT, @base, planner: planner).pairs(names)
      end

      # Planning loads most of relspec: only when a spec must be planned.
      def planner
        lambda do |path|
          require_relative "../plan"
          Plan.compute(path, timeout: @timeout).lock
        end
      end
    end
  end
end
