# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/cause"
require "relspec/catalog/shadowed_gems"

RSpec.describe Relspec::Plan::Cause do
  it "writes a chain as `relspec why` and the report show it: each step under the one it explains" do
    cause = described_class.depends_on("base/types", described_class.blacklisted("base/types", "own API"))
    expect(described_class.steps(cause.chain)).to eq(["  depends on base/types", '    └ blacklisted by "base/types" (own API)'])
    expect(described_class.steps([])).to eq([])
  end

  it "keeps text from the spec and the workspace on one printable line" do
    expect(described_class.left_out("gui/**", "qt4\nforged").to_s).to eq('left out by "gui/**" (qt4\\nforged)')
    expect(described_class.blacklisted("base/types", "x\e[2J").to_s).to eq('blacklisted by "base/types" (x\\e[2J)')
    expect(described_class.blacklisted("base/types", nil).to_s).to eq('blacklisted by "base/types"')
    expect(described_class.pinned("abc", "v1\r").to_s).to eq("pinned to abc (v1\\r)")
    expect(described_class.nonexistent_osdeps(%W[qt\n4 boost], "bookworm").to_s)
      .to eq("osdeps qt\\n4, boost are nonexistent on bookworm")
  end

  it "says which gem of the release shadows the distribution's package" do
    shadowing = Relspec::Catalog::ShadowedGems::Shadowing.new(deb: "ruby-dry-types", version: "1.2.2-2", codename: "trixie",
                                                              via: [], gem: "dry-core", packaged: "1.2.0")
    expect(described_class.shadowed_gem(shadowing).chain)
      .to eq(["not taken from the distribution: ruby-dry-types 1.2.2-2 (trixie) depends on dry-core, which the release " \
              "packages at 1.2.0"])
    forged = shadowing.to_h.merge(gem: "core\e[2J")
    expect(described_class.shadowed_gem(Relspec::Catalog::ShadowedGems::Shadowing.new(**forged)).to_s).to include("core\\e[2J")
  end

  it "chains a dependency's cause" do
    cause = described_class.depends_on("base/types", described_class.missing)
    expect(cause.chain).to eq(["depends on base/types", "missing in all ancestors"])
    expect(cause.depth).to eq(1)
  end
end
