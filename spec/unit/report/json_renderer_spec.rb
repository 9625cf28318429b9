# frozen_string_literal: true

require_relative "../unit_helper"
require "json"
require "relspec/report/page"
require "relspec/report/json_renderer"

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
end
