# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/abi/interface_verdict"

RSpec.describe Relspec::Abi::InterfaceVerdict do
  def evidence(path, check, outcome, detail = nil)
    described_class::Evidence.new(path: path, check: check, outcome: outcome, detail: detail)
  end

  it "is unchanged when every comparison found the same interface, and says what was compared" do
    verdict = described_class.of(package: "base/a", version: "1-2", against: "1-1",
                                 evidence: [evidence("lib/liba.so.1", :abi, :compatible, "1 Added function"),
                                            evidence("include/a.h", :bytes, :identical)])
    expect(verdict.unchanged?).to be(true)
    expect(verdict.changes).to eq([])
    expect(verdict.evidence.map(&:path)).to eq(["include/a.h", "lib/liba.so.1"])
    expect(verdict.summary).to eq("interface of base/a unchanged from 1-1: 1 files identical, liba.so.1 compatible")
    expect(verdict).to be_frozen
    expect(verdict.evidence.first).to be_frozen
  end

  it "is changed by any other outcome, naming the first three changes" do
    verdict = described_class.of(package: "base/a", version: "1-2", against: "1-1",
                                 evidence: [evidence("a", :bytes, :differs), evidence("b", :bytes, :added),
                                            evidence("c", :bytes, :removed), evidence("d", :abi, :changed, "1 Changed"),
                                            evidence("e", :bytes, :identical)])
    expect(verdict.unchanged?).to be(false)
    expect(verdict.changes.map(&:path)).to eq(%w[a b c d])
    expect(verdict.summary).to eq("interface of base/a changed from 1-1: a: differs; b: added; c: removed and 1 more")
  end
end
