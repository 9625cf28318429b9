# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/target"
require "relspec/mirror/proof"
require "relspec/mirror/report"

RSpec.describe Relspec::Mirror::Report do
  def check(name, status, problems = [])
    Relspec::Mirror::Proof::Check.new(name: name, status: status, problems: problems, detail: "d").freeze
  end

  def target_report(missing: [], checks: [check("static", "passed"), check("dynamic", "passed")])
    described_class::TargetReport.new(target: Relspec::Target.parse("bookworm/amd64"),
                                      counts: { "total" => 3, "release" => 1, "inherited" => 0, "distribution" => 2,
                                                "required" => 1, "bytes" => 2_500_000 },
                                      changes: nil, missing: missing, checks: checks)
  end

  it "is complete only when nothing is missing, no proof failed and the static proof passed" do
    expect(described_class.new("r", [target_report])).to be_complete
    expect(described_class.new("r", [target_report(missing: ["x (needed by y)"])])).not_to be_complete
    expect(described_class.new("r", [target_report(checks: [check("static", "passed"), check("dynamic", "failed")])]))
      .not_to be_complete
    expect(described_class.new("r", [target_report(checks: [check("static", "skipped")])])).not_to be_complete
    expect(described_class.new("r", [target_report(checks: [check("static", "passed"), check("dynamic", "skipped")])]))
      .to be_complete
  end

  it "says the same facts as text, markdown and JSON" do
    report = described_class.new("r", [target_report(missing: ["libx (needed by app 1)"])])
    expect(report.text).to eq(<<~TEXT)
      bookworm/amd64: NOT complete — 3 packages (1 of the release, 0 of them inherited from its ancestors; 2 from the distribution; 1 for the minimal system), 2.5 MB
        missing: libx (needed by app 1)
        static proof: passed (d)
        dynamic proof: passed (d)
    TEXT
    expect(report.markdown).to include("## bookworm/amd64: NOT complete", "- missing: libx (needed by app 1)")
    expect(JSON.parse(report.render("json")).dig("targets", "bookworm/amd64", "checks", "static", "status")).to eq("passed")
  end

  it "is not complete, nor any of its targets, when the mirror's files are not what its indices say" do
    report = described_class.new("r", [target_report], files: check("files", "failed", ["pool/x.deb is in the pool but no index names it"]))
    expect(report).not_to be_complete
    expect(report.text).to start_with("bookworm/amd64: NOT complete").and end_with(
      "files: failed (d)\n  pool/x.deb is in the pool but no index names it\n"
    )
    expect(report.markdown).to include("## bookworm/amd64: NOT complete", "## Files: **failed** (d)\n- pool/x.deb is in the pool")
    expect(JSON.parse(report.render("json")).values_at("complete", "files"))
      .to eq([false, { "status" => "failed", "detail" => "d", "problems" => ["pool/x.deb is in the pool but no index names it"] }])
    expect(described_class.new("r", [target_report], files: check("files", "passed"))).to be_complete
  end

  it "says which of the release's packages were kept over the distribution's higher versions" do
    one = described_class::TargetReport.new(**target_report.to_h, pinned: ["rock-a 1.0 of r is kept; the distribution's 9.0 (bookworm) is not mirrored"])
    report = described_class.new("r", [one])
    expect(report).to be_complete
    expect(report.text.lines[1]).to eq("  pinned: rock-a 1.0 of r is kept; the distribution's 9.0 (bookworm) is not mirrored\n")
    expect(report.markdown).to include("\n- pinned: rock-a 1.0 of r is kept")
    expect(JSON.parse(report.render("json")).dig("targets", "bookworm/amd64", "pinned").size).to eq(1)
  end
end
