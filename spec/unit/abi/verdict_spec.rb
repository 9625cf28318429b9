# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/abi/verdict"

# abidiff's reports as abigail-tools 2.2 prints them (taken from real runs on
# small libraries and on base/logging).
RSpec.describe Relspec::Abi::Verdict do
  let(:added) do
    <<~TEXT
      Functions changes summary: 0 Removed, 0 Changed, 1 Added function
      Variables changes summary: 0 Removed, 0 Changed, 0 Added variable

      1 Added function:

        [A] 'function int h()'    {h}

    TEXT
  end
  let(:removed) do
    <<~TEXT
      Functions changes summary: 1 Removed, 0 Changed, 0 Added function
      Variables changes summary: 0 Removed, 0 Changed, 0 Added variable

      1 Removed function:

        [D] 'function int g()'    {g}

    TEXT
  end
  let(:grown) do
    <<~TEXT
      Functions changes summary: 0 Removed, 1 Changed (8 filtered out), 0 Added functions
      Variables changes summary: 0 Removed, 0 Changed, 0 Added variable

      1 function with some indirect sub-type change:

        [C] 'method base::logging::Logger::Logger()' has some indirect sub-type changes:
              type size changed from 1088 to 1152 (in bits)
    TEXT
  end

  it "is unchanged when abidiff exits 0" do
    verdict = described_class.of(0, "")
    expect([verdict.verdict, verdict.summary, verdict.changes]).to eq(["unchanged", [], []])
  end

  it "is compatible when the change only adds, with the summary and the changes without blank lines" do
    verdict = described_class.of(4, added)
    expect(verdict.verdict).to eq("compatible")
    expect(verdict.summary).to eq(["Functions changes summary: 0 Removed, 0 Changed, 1 Added function",
                                   "Variables changes summary: 0 Removed, 0 Changed, 0 Added variable"])
    expect(verdict.changes).to eq(["1 Added function:", "  [A] 'function int h()'    {h}"])
  end

  it "is changed when something changed underneath (filtered-out counts do not matter)" do
    verdict = described_class.of(4, grown)
    expect(verdict.verdict).to eq("changed")
    expect(verdict.changes.last).to eq("        type size changed from 1088 to 1152 (in bits)")
  end

  it "is incompatible when abidiff sets its incompatible bit (removed functions)" do
    expect(described_class.of(12, removed).verdict).to eq("incompatible")
  end

  it "keeps only the first changes" do
    report = "Functions changes summary: 0 Removed, 3 Changed, 0 Added functions\n#{(1..30).map { |n| "line #{n}\n" }.join}"
    expect(described_class.of(4, report).changes).to eq((1..12).map { |n| "line #{n}" })
  end

  it "orders the verdicts for --fail-on" do
    changed = described_class.of(4, grown)
    expect([changed.at_least?("changed"), changed.at_least?("incompatible")]).to eq([true, false])
    expect(described_class.of(12, removed).at_least?("changed")).to be(true)
    expect(described_class.of(4, added).at_least?("changed")).to be(false)
  end
end
