# frozen_string_literal: true

require_relative "../plan"
require_relative "../release_specs/library"
require_relative "../project"
require_relative "../diff"

module Relspec
  module Diff
    # `relspec plan --check`: is the committed releases/<release>/lock.yml
    # the lock a plan would write now? When not, which recorded inputs moved
    # and what the decisions became (as `relspec diff` shows them). Reads
    # only; the CLI prints the verdicts.
    module LockCheck
      # Sections of the lock, and what a difference in them means.
      INPUTS = {
        "spec_digest" => "the spec (or one of its ancestors' specs) changed",
        "ancestors" => "an ancestor's repository provides other packages",
        "packages" => "the workspace's sources moved",
        "history" => "the build history differs",
        "warnings" => "the plan's warnings differ",
        "notes" => "the plan's notes differ"
      }.freeze
      DEPENDS = "the builds' recorded dependencies (depends:) differ; a lock written before relspec recorded " \
                "them lacks them"

      # +status+: :current, :missing or :stale; +reasons+ (stale): what moved;
      # +diff+ (stale): the decisions' diff, without its release line (which
      # would repeat the path).
      Verdict = Struct.new(:path, :status, :reasons, :diff, keyword_init: true) do
        def current?
          status == :current
        end
      end

      module_function

      # The specs to check: +paths+, or every spec of the project's specs/
      # (+project+: a Project) when none is named.
      def spec_paths(paths, project)
        return paths unless paths.empty?

        specs = project.specs_dir
        raise Error, "no #{specs}/ folder here: run from the project root or name the spec files" unless File.directory?(specs)

        library = ReleaseSpec::Library.new(specs)
        raise Error, "#{specs}/ holds no <release>.yml file" if library.names.empty?

        library.paths
      end

      # +planned+: a Plan::Result.
      def verdict(planned)
        path = planned.lock_path
        committed = File.file?(path) ? File.read(path) : nil
        return Verdict.new(path: path, status: :current) if committed == planned.lock_text
        return Verdict.new(path: path, status: :missing) unless committed

        old = LockView.parse(committed, source: path)
        new = LockView.snapshot(planned.lock, source: "the plan")
        reasons = reasons(Plan::LockParser.parse(committed, file: path, release: nil), planned.lock)
        text = Diff.render([ReleaseDiff.compare(old, new)], "text")
        Verdict.new(path: path, status: :stale, reasons: reasons, diff: text.lines.drop(1).join)
      end

      def reasons(committed, computed)
        before = committed.to_h
        after = computed.to_h
        found = INPUTS.filter_map { |key, meaning| meaning unless before[key] == after[key] }
        # said only when nothing else of the decisions differs: when they
        # do, depends: follows them and the decision diff says more
        found << DEPENDS if before["targets"] != after["targets"] &&
                            without_depends(before["targets"]) == without_depends(after["targets"])
        found
      end

      def without_depends(targets)
        targets.transform_values { |entries| entries.transform_values { |entry| entry.except("depends") } }
      end
    end
  end
end
