# frozen_string_literal: true

require_relative "../unit_helper"
require "json"
require "relspec/target"
require "relspec/abi/verdict"
require "relspec/abi/report"

RSpec.describe Relspec::Abi::Report do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:changed) do
    Relspec::Abi::Verdict.of(4, "Functions changes summary: 0 Removed, 1 Changed, 0 Added functions\n\n  [C] 'f' changed\n")
  end
  let(:report) do
    entries = [
      described_class::Entry.new(package: "base/logging", library: "libbase-logging.so", against: "parent", verdict: changed),
      described_class::Entry.new(package: "base/types", library: "libbase-types.so", against: "parent",
                                 verdict: Relspec::Abi::Verdict.of(0, "")),
      described_class::Entry.new(package: "drivers/new", library: "libnew.so", against: nil, verdict: nil)
    ]
    described_class.new(release: "child", targets: [described_class::TargetReport.new(target: target, entries: entries)])
  end

  it "prints each library's verdict, and abidiff's summary and first changes for the ones that moved" do
    expect(report.render("text")).to eq(<<~TEXT)
      child bookworm/amd64: 3 libraries: 1 unchanged, 1 changed, 1 new
        libbase-logging.so (base/logging): changed against parent
          Functions changes summary: 0 Removed, 1 Changed, 0 Added functions
            [C] 'f' changed
        libbase-types.so (base/types): unchanged against parent
        libnew.so (drivers/new): new
    TEXT
  end

  it "gives JSON entries with package, library, verdict and against per target" do
    json = JSON.parse(report.render("json"))
    expect(json["release"]).to eq("child")
    expect(json["targets"]["bookworm/amd64"].map { |entry| entry.slice("package", "library", "verdict", "against") })
      .to eq([{ "package" => "base/logging", "library" => "libbase-logging.so", "verdict" => "changed", "against" => "parent" },
              { "package" => "base/types", "library" => "libbase-types.so", "verdict" => "unchanged", "against" => "parent" },
              { "package" => "drivers/new", "library" => "libnew.so", "verdict" => "new", "against" => nil }])
  end

  it "gives markdown a table and a folded detail per library that moved" do
    markdown = report.render("markdown")
    expect(markdown).to include("| `libbase-logging.so` | base/logging | **changed** | parent |\n")
    expect(markdown).to include("| `libnew.so` | drivers/new | **new** | - |\n")
    expect(markdown.scan("<details>").size).to eq(1)
  end

  it "fails at the threshold or worse, never for new libraries" do
    expect([report.fails?("changed"), report.fails?("incompatible")]).to eq([true, false])
  end

  it "says when a target built no shared library" do
    empty = described_class.new(release: "r", targets: [described_class::TargetReport.new(target: target, entries: [])])
    expect(empty.render("text")).to eq("r bookworm/amd64: no shared library built\n")
  end
end
