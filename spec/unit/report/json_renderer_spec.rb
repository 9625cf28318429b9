# frozen_string_literal: true

require_relative "../unit_helper"
require "json"
require "relspec/report/page"
require "relspec/report/json_renderer"
require "relspec/report/abi_summary"

RSpec.describe Relspec::Report::JsonRenderer do
  it "writes the page's data as a versioned document, leaving out what is not known" do
    cell = Relspec::Report::Cell.new(package: "base/cmake", decision: "inherit", from: "base", version: "1.0-1")
    view = Relspec::Report::TargetView.new(target: "bookworm/amd64", backend: nil, cells: [cell], totals: { "inherit" => 1 },
                                           build_seconds: 0, blockers: [], critical_path: [], changes: nil)
    text = described_class.render(Relspec::Report::Page.new(release: "child", ancestor: nil, targets: [view]))
    expect(text).to end_with("}\n")
    expect(JSON.parse(text)).to eq(
      "relspec_report" => 1, "release" => "child",
      "targets" => [{ "target" => "bookworm/amd64", "totals" => { "inherit" => 1 }, "build_seconds" => 0,
                      "packages" => { "base/cmake" => { "package" => "base/cmake", "decision" => "inherit",
                                                        "from" => "base", "version" => "1.0-1" } },
                      "blocked" => [], "critical_path" => [] }]
    )
  end

  it "adds a target's ABI summary when it has one" do
    abi = Relspec::Report::AbiSummary.new(counts: { "changed" => 1 }, listed: [
      Relspec::Report::AbiLibrary.new(package: "a", library: "liba.so", verdict: "changed",
                                      against: "base")
    ])
    view = Relspec::Report::TargetView.new(target: "bookworm/amd64", cells: [], totals: {}, build_seconds: 0, blockers: [],
                                           critical_path: [], abi: abi)
    data = JSON.parse(described_class.render(Relspec::Report::Page.new(release: "child", targets: [view])))
    expect(data["targets"].first["abi"]).to eq("counts" => { "changed" => 1 }, "listed" => [
      { "package" => "a", "library" => "liba.so", "verdict" => "changed",
        "against" => "base" }
    ])
  end
end
