# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/version"
require "relspec/plan/history"
require "relspec/plan/target"
require "relspec/debian/package_version"

RSpec.describe Relspec::Plan::History do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }

  def version(upstream, revision) = Relspec::Debian::PackageVersion.new(upstream, revision, "bookworm")

  it "records builds per target, package and upstream version, keeping earlier ones" do
    history = described_class.empty.with(target, "a", version("1.0", 2), "d1").with(target, "a", version("0.9", 1), "d0")
    expect(history.build(target, "a", "1.0").to_h).to eq(revision: 2, debian_digest: "d1", kept: nil)
    expect(history.size).to eq(2)
    expect(history.to_h).to eq("bookworm/amd64" => { "a" => { "0.9" => { "revision" => 1, "debian_digest" => "d0" },
                                                              "1.0" => { "revision" => 2, "debian_digest" => "d1" } } })
  end

  it "records why the early cutoff kept a revision, and writes it only then" do
    history = described_class.empty.with_all([[target, "a", version("1.0", 1), "d2", "the interface of b did not change"],
                                              [target, "b", version("2.0", 3), "d3"]])
    expect(history.build(target, "a", "1.0").kept).to eq("the interface of b did not change")
    expect(history.to_h["bookworm/amd64"]).to eq(
      "a" => { "1.0" => { "revision" => 1, "debian_digest" => "d2", "kept" => "the interface of b did not change" } },
      "b" => { "2.0" => { "revision" => 3, "debian_digest" => "d3" } }
    )
  end

  it "lists the upstream versions recorded for a package on a target (none for others)" do
    history = described_class.empty.with(target, "a", version("1.0", 1), "d").with(target, "a", version("0.9", 1), "d")
    expect(history.upstreams(target, "a").sort).to eq(%w[0.9 1.0])
    expect(history.upstreams(target, "b")).to eq([])
    expect(described_class.empty.upstreams(target, "a")).to eq([])
  end
end
