# frozen_string_literal: true

require_relative "../plan"
require_relative "../release_spec/library"
require_relative "../diff"

module Relspec
  module CLI
    # `relspec plan --check [SPEC…]`: the CI gate for committed release
    # state. Plans every spec (default: all of specs/) and compares the lock
    # it would write with releases/<release>/lock.yml; a lock that differs
    # is named with what changed — the decisions (as `relspec diff` shows
    # them) and which recorded inputs moved. Writes nothing. Returns 1 when
    # any lock is out of date.
    class PlanCheckCommand
      SPECS = "specs"
      # Sections of the lock, and what a difference in them means.
      INPUTS = {
        "spec_digest" => "the spec (or one of its ancestors' specs) changed",
        "ancestors" => "an ancestor's repository provides other packages",
        "packages" => "the workspace's sources moved",
        "history" => "the build history differs",
        "warnings" => "the plan's warnings differ",
        "notes" => "the plan's notes differ"
      }.freeze

      def initialize(paths:, timeout:, out:)
        @paths = paths
        @timeout = timeout
        @out = out
      end

      def call
        stale = spec_paths.reject { |path| current?(Plan.compute(path, timeout: @timeout)) }
        return 0 if stale.empty?

        @out.puts("#{stale.size} lock#{'s' unless stale.size == 1} out of date: run `relspec compile SPEC` " \
                  "(or `relspec plan --write SPEC`) and commit releases/")
        1
      end

      private

      def spec_paths
        return @paths unless @paths.empty?

        library = ReleaseSpec::Library.new(SPECS)
        raise Error, "no #{SPECS}/ folder here: run from the project root or name the spec files" unless File.directory?(SPECS)
        raise Error, "#{SPECS}/ holds no <release>.yml file" if library.names.empty?

        library.paths
      end

      def current?(result)
        path = result.lock_path
        committed = File.file?(path) ? File.read(path) : nil
        return true if committed == result.lock_text

        unless committed
          @out.puts("#{path}: missing")
          return false
        end
        @out.puts("#{path}: out of date")
        old = Diff::LockView.parse(committed, source: path)
        new = Diff::LockView.snapshot(result.lock, source: "the plan")
        reasons(Plan::LockParser.parse(committed, file: path, release: nil), result.lock).each { |reason| @out.puts("  #{reason}") }
        text = Diff.render([Diff::ReleaseDiff.compare(old, new)], "text")
        @out.write(text.lines.drop(1).join) # the release line repeats the path
        false
      end

      DEPENDS = "the builds' recorded dependencies (depends:) differ; a lock written before relspec recorded " \
                "them lacks them"

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
