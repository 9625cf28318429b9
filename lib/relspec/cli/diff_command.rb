# frozen_string_literal: true

require_relative "../diff"

module Relspec
  module CLI
    # `relspec diff OLD NEW` and `relspec diff --base REF [SPEC…]`: the
    # release diff for review. Returns 1 when --exit-code is given and
    # something differs, or when more packages are rebuilt than
    # --fail-on-rebuilds allows; 0 otherwise.
    class DiffCommand
      def initialize(paths:, base:, format:, exit_code:, fail_on_rebuilds:, timeout:, out:, err:, color: false, abi_out: nil)
        @abi_out = abi_out
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

        diffs = Diff.run(paths: @paths, base: @base, timeout: @timeout)
        abi = @abi_out ? Diff::AbiSection.new(root: project_root, out: @abi_out).reports(diffs) : {}
        @out.write(Diff.render(diffs, @format, color: @color, abi: abi))
        rebuilds = diffs.sum(&:rebuilds)
        if @fail_on_rebuilds && rebuilds > @fail_on_rebuilds
          @err.puts("relspec diff: #{rebuilds} rebuilds, more than the #{@fail_on_rebuilds} allowed (--fail-on-rebuilds)")
          return 1
        end
        @exit_code && diffs.any?(&:changed?) ? 1 : 0
      end

      private

      # The project of the specs given, else the current folder's.
      def project_root
        spec = @paths.find { |path| File.basename(File.dirname(File.expand_path(path))) == "specs" }
        spec ? Project.of_spec(spec).root : Diff::PROJECT_ROOT
      end
    end
  end
end
