# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/report/abi_summary"
require "relspec/abi/report"
require "relspec/abi/verdict"

# The summary is made from `relspec abi`'s own entries and verdicts.
RSpec.describe Relspec::Report::AbiSummary do
  def entry(package, library, verdict, against: "base")
    Relspec::Abi::Report::Entry.new(package: package, library: library, against: verdict && against,
                                    verdict: verdict && Relspec::Abi::Verdict.new(verdict: verdict, summary: [], changes: []))
  end

  it "says nothing when no library was compared with an ancestor's dump" do
    expect(described_class.of([entry("a", "liba.so", nil)])).to be_nil
    expect(described_class.of([])).to be_nil
  end

  it "counts every verdict in a fixed order and lists the libraries to review, incompatible first" do
    summary = described_class.of([entry("z", "libz.so", "changed"), entry("a", "liba.so", "unchanged"),
                                  entry("b", "libb.so.1", "incompatible", against: "grand"), entry("c", "libc.so", nil),
                                  entry("a", "liba2.so", "changed"), entry("d", "libd.so", "compatible")])
    expect(summary.counts).to eq("unchanged" => 1, "compatible" => 1, "changed" => 2, "incompatible" => 1, "new" => 1)
    expect(summary.counts.keys).to eq(%w[unchanged compatible changed incompatible new])
    expect(summary.listed.map { |one| [one.verdict, one.package, one.library, one.against] })
      .to eq([%w[incompatible b libb.so.1 grand], %w[changed a liba2.so base], %w[changed z libz.so base]])
    expect(summary.to_h["listed"].first).to eq("package" => "b", "library" => "libb.so.1", "verdict" => "incompatible",
                                               "against" => "grand")
    expect(summary.to_h).not_to have_key("error")
  end

  it "keeps why the verdicts could not be computed" do
    expect(described_class.failed("the ABI dump x has changed").to_h)
      .to eq("counts" => {}, "listed" => [], "error" => "the ABI dump x has changed")
  end
end
