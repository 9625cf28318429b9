# frozen_string_literal: true

module Relspec
  module Report
    # One package on one target: the lock's decision (+decision+ "inherit",
    # "build", "published", "system" or "unavailable"; +from+ the release it
    # is inherited from), the version, and the last build's +status+
    # ("built", "failed", "skipped", "not built yet", or nil when the release
    # does not build it). +blocked_by+: the failed sources a skipped build
    # waited for; +log+: the whole log, relative to the page; +first_error+:
    # the log's first error line (or the failure's reason); +causes+: why it
    # is built or unavailable, one line per step (`relspec why`).
    Cell = Struct.new(:package, :source, :decision, :from, :version, :status, :reason, :blocked_by, :duration, :log,
                      :first_error, :causes, keyword_init: true) do
      def to_h
        { "package" => package, "source" => source, "decision" => decision, "from" => from, "version" => version,
          "status" => status, "reason" => reason, "blocked_by" => blocked_by, "duration" => duration, "log" => log,
          "first_error" => first_error, "causes" => causes }.compact
      end
    end

    # A failed build and the packages whose builds were skipped because of it.
    Blocker = Struct.new(:source, :package, :blocked, keyword_init: true) do
      def to_h
        { "source" => source, "package" => package, "blocked" => blocked }
      end
    end

    # One build on the critical path: the chain of build-dependencies whose
    # build times add up to the most, which bounds a build's wall time
    # however many jobs run.
    Step = Struct.new(:source, :duration, keyword_init: true) do
      def to_h
        { "source" => source, "duration" => duration }
      end
    end

    # A package whose decision differs from the ancestor's lock (Diff's
    # PackageChange, as text): +change+ is Diff::KINDS' wording.
    Change = Struct.new(:package, :change, :old, :new, keyword_init: true) do
      def to_h
        { "package" => package, "change" => change, "old" => old, "new" => new }.compact
      end
    end

    # One target: its cells by package, totals (name => count, in a fixed
    # order), the blockers (most blocked first), the critical path of the
    # last build, the changes against the ancestor (nil: no ancestor
    # lock to compare with) and the ABI verdicts' AbiSummary (nil: no dumps
    # compared).
    TargetView = Struct.new(:target, :backend, :cells, :totals, :build_seconds, :blockers, :critical_path, :changes,
                            :abi, keyword_init: true) do
      def critical_seconds
        critical_path.sum(&:duration)
      end

      # The Cell of +package+, nil when the lock has none on this target.
      def cell(package)
        cells.find { |one| one.package == package }
      end

      def to_h
        { "target" => target, "backend" => backend, "totals" => totals, "build_seconds" => build_seconds,
          "packages" => cells.to_h { |cell| [cell.package, cell.to_h] }, "blocked" => blockers.map(&:to_h),
          "critical_path" => critical_path.map(&:to_h), "changes" => changes&.map(&:to_h),
          "abi" => abi&.to_h }.compact
      end
    end

    # The whole page of one release: +ancestor+ the release the changes are
    # against (nil: none).
    Page = Struct.new(:release, :ancestor, :targets, keyword_init: true) do
      # The packages of every target, sorted: the rows of the matrix.
      def packages
        targets.flat_map { |view| view.cells.map(&:package) }.uniq.sort
      end

      def to_h
        { "relspec_report" => 1, "release" => release, "ancestor" => ancestor, "targets" => targets.map(&:to_h) }.compact
      end
    end
  end
end
