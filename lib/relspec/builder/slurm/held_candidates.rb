# frozen_string_literal: true

require_relative "../build_plan"
require_relative "../early_cutoff"

module Relspec
  module Builder
    module Slurm
      # The early cutoff in a Slurm run (docs/scale-out.md, "Early
      # cutoff"): the candidates whose jobs stay held until they are
      # decided, and what each decision does. The same verdicts as a local
      # run (Abi::InterfaceVerdicts) decide; only the order differs: a job
      # of a package built in the run is released at once, so a candidate
      # in its closure cannot be kept (the package names its new version,
      # which the repository would never hold) and is built, saying why, as
      # the local run's "built after all" does; a kept package in the
      # closure of one built is built after all, its job submitted again.
      class HeldCandidates
        # +keep+: the candidate is kept (its job cancelled); +revoke+: the
        # kept entries to build after all, first, in plan order.
        Decision = Struct.new(:keep, :revoke, keyword_init: true)

        # +verdicts+: Abi::InterfaceVerdicts (or NoVerdicts); +entries+:
        # the plan's; +pending+: the entries this relspec builds or decides;
        # +kept+: the sources an earlier run kept, reused; +released+: the
        # pending candidates an earlier relspec of this run already let
        # build (a job released or finished): they are built.
        def initialize(verdicts, entries, pending:, kept:, released:)
          @verdicts = verdicts
          @entries = entries.to_h { |entry| [entry.source, entry] }
          @order = entries.each_with_index.to_h { |entry, index| [entry.source, index] }
          deciding = verdicts.deciding?
          @undecided = pending.select { |entry| deciding && entry.cutoff }.to_h { |entry| [entry.source, true] }
          @kept = kept.to_h { |source| [source, true] }
          @forced = {}
          @revoked = []
          commit(pending.reject { |entry| @undecided[entry.source] && !released.include?(entry.source) }.map(&:source),
                 released)
        end

        # The kept packages of earlier runs that a package built now names
        # at their new version: built after all (plan order).
        def revoked_at_start
          @revoked.map { |source| @entries.fetch(source) }
        end

        # True while +source+ waits for its decision (its job held).
        def undecided?(source)
          @undecided.key?(source)
        end

        # The undecided candidates whose closure has its outcomes
        # (+settled+: sources built or kept, in this run or before), in
        # plan order.
        def ready(settled)
          @undecided.keys.sort_by { |source| @order[source] }.select do |source|
            closure(source).all? { |need| settled.include?(need) }
          end.map { |source| @entries.fetch(source) }
        end

        # Decides +entry+ (undecided) with the run's verdicts; the verdicts
        # record the keep, the rebuild or why it was built after all.
        def decide(entry)
          @undecided.delete(entry.source)
          cutoff = @verdicts.keep(entry)
          by = @forced[entry.source]
          if cutoff&.keep? && by
            @verdicts.revoke(entry.source, forced_by(by, entry.source))
          elsif cutoff&.keep?
            return Decision.new(keep: @kept[entry.source] = true, revoke: [])
          end
          Decision.new(keep: false, revoke: revoke_for(entry.source).map { |source| @entries.fetch(source) })
        end

        private

        # Packages built in the run force the candidates of their closure
        # to be built, and revoke the keeps of earlier runs there.
        def commit(sources, released)
          sources.sort_by { |source| @order[source] }.each do |source|
            @forced[source] ||= source if released.include?(source)
            closure(source).each { |need| @forced[need] ||= source if @undecided[need] }
            @revoked.concat(revoke_for(source))
          end
        end

        # The kept packages of +source+'s closure, revoked now.
        def revoke_for(source)
          closure(source).select { |need| @kept[need] }.each do |need|
            @kept.delete(need)
            @verdicts.revoke(need, EarlyCutoff.built_after_all(source))
          end
        end

        # Why the candidate +source+, forced by +builder+ (a package built
        # in the run), is built although its closure kept its interface.
        def forced_by(builder, source)
          builder == source ? "built: an earlier relspec of this run released its job" : EarlyCutoff.built_after_all(builder)
        end

        def closure(source)
          BuildPlan.closure(@entries, source)
        end
      end
    end
  end
end
