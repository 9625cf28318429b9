# frozen_string_literal: true

module Relspec
  module Report
    # The ABI verdicts of one target, summed up for the page: how many
    # libraries got each verdict, and the ones to review (changed or
    # incompatible) by name. Made from `relspec abi`'s own entries
    # (Abi::Report::Entry); +error+: why the verdicts could not be computed
    # (then there are no counts).
    AbiSummary = Struct.new(:counts, :listed, :error, keyword_init: true) do
      def to_h
        { "counts" => counts, "listed" => listed.map(&:to_h), "error" => error }.compact
      end
    end

    # One library to review: its package, its file name, its verdict and the
    # release it was compared against.
    AbiLibrary = Struct.new(:package, :library, :verdict, :against, keyword_init: true) do
      def to_h
        { "package" => package, "library" => library, "verdict" => verdict, "against" => against }
      end
    end

    # Its rules.
    class AbiSummary
      # The verdicts in the order the page counts them (Abi::Verdict::ORDER,
      # then the libraries nothing was compared with).
      VERDICTS = %w[unchanged compatible changed incompatible new].freeze
      REVIEW = %w[changed incompatible].freeze

      # The summary of +entries+ (Abi::Report::Entry of one target), nil when
      # none was compared with an ancestor's dump: without dumps on both
      # sides the page says nothing.
      def self.of(entries)
        return nil if entries.none?(&:against)

        tally = entries.map(&:name).tally
        listed = entries.select { |entry| REVIEW.include?(entry.name) }.map do |entry|
          AbiLibrary.new(package: entry.package, library: entry.library, verdict: entry.name, against: entry.against).freeze
        end
        new(counts: VERDICTS.to_h { |name| [name, tally.fetch(name, 0)] }.freeze,
            listed: listed.sort_by { |one| [-REVIEW.index(one.verdict), one.package, one.library] }.freeze).freeze
      end

      # The verdicts could not be computed (a dump changed since it was
      # recorded, abidiff failed, an ancestor's index is broken): the page
      # says why instead of failing.
      def self.failed(message)
        new(counts: {}.freeze, listed: [].freeze, error: message).freeze
      end
    end
  end
end
