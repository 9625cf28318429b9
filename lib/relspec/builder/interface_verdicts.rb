# frozen_string_literal: true

require_relative "build_results"
require_relative "../abi/interface_check"
require_relative "../abi/comparison"

module Relspec
  module Builder
    # The early cutoff's verdicts of one run (docs/abi.md, "Early cutoff"):
    # each package built is compared, when its build finishes and before
    # its files replace the old ones, with the build it replaces in the
    # target folder, as build-results.yml recorded it when the run started.
    # Only a build of another version whose files are all still there with
    # the bytes recorded is compared. Thread-safe: builds finish in worker
    # threads, records are written in the calling one.
    class InterfaceVerdicts
      # The verdicts of a run building +entries+ (plan entries) over
      # +results+ (BuildResults, as the run found them) in +dir+.
      def self.of(results, entries, dir)
        new(entries.to_h { |entry| [entry.source, results[entry.source]] }, dir)
      end

      # +previous+: source => BuildResults::Record (or nil) before the run;
      # +dir+: the target folder; +compare+: how two dumps are compared.
      def initialize(previous, dir, compare: Abi::Comparison.method(:compare))
        @previous = previous
        @dir = dir
        @check = Abi::InterfaceCheck.new(compare: compare)
        @verdicts = {}
        @lock = Mutex.new
      end

      # Decides the verdict of +entry+'s new build, whose produced files
      # are +files+ (paths), and keeps it for #[]; nil when there is
      # nothing to compare.
      def decide(entry, files)
        previous = @previous[entry.source]
        return nil unless comparable?(previous, entry)

        interface = interface_of(entry, previous, files)
        @lock.synchronize { @verdicts[entry.source] = interface }
      end

      # The verdict decided for +source+ in this run, or nil.
      def [](source)
        @lock.synchronize { @verdicts[source] }
      end

      def comparable?(previous, entry)
        !!previous&.built? && previous.version != entry.version && previous.files.all? { |file| file.intact?(@dir) }
      end

      private

      def interface_of(entry, previous, files)
        old = Abi::InterfaceCheck::Side.of(previous.version, previous.files.map { |file| File.join(@dir, file.name) })
        new = Abi::InterfaceCheck::Side.of(entry.version, files)
        BuildResults::Interface.of(@check.decide(entry.package, old: old, new: new))
      rescue ToolError => e
        # a comparison that cannot be made proves nothing: the interface
        # counts as changed, and the build that succeeded stays built
        BuildResults::Interface.new(against: previous.version, verdict: "changed", compared: 0,
                                    changes: ["not compared: #{e.message}"].freeze).freeze
      end
    end
  end
end
