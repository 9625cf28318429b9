# frozen_string_literal: true

require_relative "../project"

module Relspec
  module Diff
    # The ABI verdicts a release diff shows (docs/abi.md, docs/diff.md): for
    # each changed release whose spec is in the project and whose builds are
    # in +out+ (`relspec diff --abi-out`), `relspec abi`'s report of the
    # libraries of the packages the diff rebuilds, per target. Releases
    # without dumps on both sides show nothing (a library with no ancestor
    # dump is "new").
    class AbiSection
      # +root+: the project folder holding specs/; +out+: where the new side
      # was compiled and built.
      def initialize(root:, out:)
        @project = Project.new(root)
        @out = out
      end

      # release => Abi::Report of the rebuilt packages' libraries, for the
      # +diffs+ (ReleaseDiffs) that have a spec and a build.
      def reports(diffs)
        require_relative "../abi" # abidiff and the build results: only when asked for
        diffs.select(&:changed?).each_with_object({}) do |diff, reports|
          spec = File.join(@project.specs_dir, "#{diff.release}.yml")
          next unless File.file?(spec) && File.directory?(File.join(@out, diff.release))

          reports[diff.release] = only_rebuilt(Abi.run(spec, out: @out), diff)
        end
      end

      private

      def only_rebuilt(report, diff)
        rebuilt = diff.targets.to_h do |target|
          [target.target.to_s, target.changes.select { |change| change.new&.built? }.map(&:package)]
        end
        targets = report.targets.map do |one|
          names = rebuilt.fetch(one.target.to_s, [])
          one.class.new(target: one.target, entries: one.entries.select { |entry| names.include?(entry.package) }.freeze).freeze
        end
        report.class.new(release: report.release, targets: targets.freeze).freeze
      end
    end
  end
end
