# frozen_string_literal: true

require "fileutils"
require "tmpdir"
require_relative "../builder/build_results"
require_relative "../builder/build_plan"
require_relative "interface_check"
require_relative "comparison"

module Relspec
  module Abi
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
      # +refused+: why the early cutoff keeps nothing in this run (the
      # spec's early_cutoff, --rebuild-dependents), or nil. +replaced+:
      # where the files of the builds replaced are, under their recorded
      # names (a Slurm job replaces them before relspec takes its build:
      # Builder::Slurm::ReplacedFiles keeps them there); default +dir+.
      def self.of(results, entries, dir, refused: nil, replaced: nil)
        new(entries.to_h { |entry| [entry.source, results[entry.source]] }, dir, entries: entries, refused: refused,
                                                                                 replaced: replaced)
      end

      # +previous+: source => Builder::BuildResults::Record (or nil) before the run;
      # +dir+: the target folder; +compare+: how two dumps are compared;
      # +entries+: the plan's entries (their build_depends give each
      # build's closure, their cutoff the early cutoff's candidates).
      def initialize(previous, dir, compare: Comparison.method(:compare), entries: [], refused: nil, replaced: nil)
        @previous = previous
        @refused = refused
        @dir = replaced || dir
        @check = InterfaceCheck.new(compare: compare)
        @entries = entries.to_h { |entry| [entry.source, entry] }
        # source => the version the repository holds, as the candidates name it
        @held = entries.flat_map { |entry| (entry.cutoff&.against || {}).to_a }.to_h.freeze
        @verdicts = {}
        @cutoffs = {}
        @lock = Mutex.new
      end

      # Decides the verdict of +entry+'s new build, whose produced files
      # are +files+ (paths), and keeps it for #[] (nil when there is
      # nothing to compare); for a candidate, what the early cutoff decides
      # (#cutoff).
      def decide(entry, files)
        previous = @previous[entry.source]
        interface = comparable?(previous, entry) ? held(interface_of(entry, previous, files), entry.source) : nil
        cutoff = entry.cutoff && !cutoff(entry.source) ? undecided(entry) : nil # #keep decides it first
        @lock.synchronize do
          @verdicts[entry.source] = interface
          @cutoffs[entry.source] ||= cutoff
        end
        interface
      end

      # What the early cutoff decides for +entry+ before it is built: the
      # verdicts of its closure exist once it is ready to build. A
      # Builder::BuildResults::Cutoff (kept for #cutoff), or nil when
      # +entry+ is no candidate.
      def keep(entry)
        return nil unless entry.cutoff

        cutoff = @refused ? refusal(entry) : cutoff_of(entry)
        @lock.synchronize { @cutoffs[entry.source] = cutoff }
      end

      # +source+, kept in this run or an earlier one, is built after all (a
      # dependent built now names its new version): +reason+ replaces the
      # keep.
      def revoke(source, reason)
        cutoff = Builder::BuildResults::Cutoff.new(keeps: @entries.fetch(source).cutoff.keeps, verdict: "rebuild",
                                                   reason: reason, evidence: [].freeze).freeze
        @lock.synchronize { @cutoffs[source] = cutoff }
      end

      # True when the run decides its candidates (the cutoff not refused).
      def deciding?
        @refused.nil?
      end

      # The verdict decided for +source+ in this run, or nil.
      def [](source)
        @lock.synchronize { @verdicts[source] }
      end

      # What the early cutoff decided for the candidate +source+ in this
      # run (a Builder::BuildResults::Cutoff), or nil.
      def cutoff(source)
        @lock.synchronize { @cutoffs[source] }
      end

      # The sources of the plan +source+ needs built first, directly or
      # through others, in plan order.
      def closure(source)
        Builder::BuildPlan.closure(@entries, source)
      end

      # A build of another version, or the kept build a kept record lists,
      # whose files are all there with the bytes recorded.
      def comparable?(previous, entry)
        !previous.nil? && (previous.built? || previous.kept?) && !previous.files.empty? &&
          previous.files_version != entry.version && previous.files.all? { |file| file.intact?(@dir) }
      end

      private

      # Keep when every build of the candidate's closure left its
      # interface unchanged (its verdict, of this run or of the earlier run
      # that built it at its planned version) or is kept itself: then
      # nothing the candidate builds against changed, also through the
      # headers of a dependency's dependency.
      def cutoff_of(entry)
        closure = closure(entry.source)
        changed = closure.lazy.filter_map { |source| rebuild_reason(entry, source) }.first
        reason = changed || "the interface of #{entry.cutoff.because.join(', ')} did not change"
        Builder::BuildResults::Cutoff.new(keeps: entry.cutoff.keeps, verdict: changed ? "rebuild" : "keep", reason: reason,
                                          evidence: changed ? [].freeze : evidence(closure)).freeze
      end

      # Why +source+ of +entry+'s closure makes it rebuilt, or nil. A
      # verdict counts only against the build the repository holds, which
      # the kept build was made against (+against+ of the plan; unknown in
      # plans written before it): a build made and not published since is
      # no baseline.
      def rebuild_reason(entry, source)
        return nil if kept_at(source)

        verdict = interface(source)
        return "#{source} has no verdict to go by" unless verdict

        held = (entry.cutoff.against || {})[source]
        if held && verdict.against.to_s != held
          return "#{source}'s new build was compared with #{verdict.against}, not with #{held} " \
                 "that the repository holds and the kept build was made against"
        end
        verdict.unchanged? ? nil : "the interface of #{source} changed"
      end

      # One line per package of a kept candidate's closure: what its
      # interface was compared against, or the version it was kept at.
      def evidence(closure)
        closure.map do |source|
          kept = kept_at(source)
          next "#{source} kept at #{kept}" if kept

          found = interface(source)
          "#{source}: #{found.compared} files compared with #{found.against}, unchanged"
        end.freeze
      end

      # A candidate built before #keep decided it: a Slurm run refusing the
      # cutoff holds no job for a decision.
      def undecided(entry)
        @refused ? refusal(entry) : cutoff_of(entry)
      end

      def refusal(entry)
        Builder::BuildResults::Cutoff.new(keeps: entry.cutoff.keeps, verdict: "rebuild", reason: @refused,
                                          evidence: [].freeze).freeze
      end

      # A build's side, its .debs unpacked into +root+ (for the headers).
      def side(version, paths, root)
        FileUtils.mkdir_p(root)
        InterfaceCheck::Side.of(version, paths, root: root)
      end

      # The version +source+ is kept at: by this run, or by an earlier one
      # at its planned version when this run neither decides nor builds it
      # (the run reuses that keep), else nil.
      def kept_at(source)
        decided, built = @lock.synchronize { [@cutoffs[source], @verdicts.key?(source)] }
        return decided.keep? ? decided.keeps : nil if decided
        return nil if built

        previous = @previous[source]
        previous&.kept? && previous.version == @entries[source]&.version ? previous.cutoff.keeps : nil
      end

      # The verdict of +source+'s build in this run (nil: nothing compared),
      # else the one an earlier run recorded at its planned version.
      def interface(source)
        built, found = @lock.synchronize { [@verdicts.key?(source), @verdicts[source]] }
        return found if built

        previous = @previous[source]
        previous&.version == @entries[source]&.version ? previous&.interface : nil
      end

      # +interface+ naming the version the repository holds of +source+
      # when it was compared with another one: a build made and not
      # published is said to be no baseline, not compared silently.
      def held(interface, source)
        held = @held[source]
        return interface if held.nil? || held == interface.against

        Builder::BuildResults::Interface.new(**interface.to_h.transform_keys(&:to_sym), held: held).freeze
      end

      def interface_of(entry, previous, files)
        Dir.mktmpdir("relspec-interface") do |work|
          old = side(previous.files_version, previous.files.map { |file| File.join(@dir, file.name) }, File.join(work, "old"))
          new = side(entry.version, files, File.join(work, "new"))
          Builder::BuildResults::Interface.of(@check.decide(entry.package, old: old, new: new))
        end
      rescue ToolError => e
        # a comparison that cannot be made proves nothing: the interface
        # counts as changed, and the build that succeeded stays built
        Builder::BuildResults::Interface.new(against: previous.files_version, verdict: "changed", compared: 0,
                                             changes: ["not compared: #{e.message}"].freeze).freeze
      end
    end
  end
end
