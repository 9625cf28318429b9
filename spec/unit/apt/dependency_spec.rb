# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/dependency"

RSpec.describe Relspec::Apt::Dependency do
  it "reads alternatives, versions, architecture qualifiers, architecture lists and profiles" do
    groups = described_class.parse("a (>= 1.0) | b, c:any [amd64 arm64], d <!nocheck>, e (<< 2:1~rc1) [!i386] <!nocheck> <cross>")
    expect(groups.map { |group| group.map(&:to_h) }).to eq([
      [{ name: "a", arch_qualifier: nil, operator: ">=", version: "1.0", architectures: [], profiles: [] },
       { name: "b", arch_qualifier: nil, operator: nil, version: nil, architectures: [], profiles: [] }],
      [{ name: "c", arch_qualifier: "any", operator: nil, version: nil, architectures: %w[amd64 arm64], profiles: [] }],
      [{ name: "d", arch_qualifier: nil, operator: nil, version: nil, architectures: [], profiles: [["!nocheck"]] }],
      [{ name: "e", arch_qualifier: nil, operator: "<<", version: "2:1~rc1", architectures: ["!i386"],
         profiles: [["!nocheck"], ["cross"]] }]
    ])
  end

  it "writes relations back as Debian writes them" do
    expect(described_class.parse("x:any (>= 1) [amd64] <!nocheck>").flatten.map(&:to_s)).to eq(["x:any (>= 1) [amd64] <!nocheck>"])
  end

  it "reads the old < and > operators as dpkg does" do
    expect(described_class.parse("a (< 1), b (> 2)").flatten.map(&:operator)).to eq(["<=", ">="])
  end

  it "lists provided names" do
    expect(described_class.provided_names("a (= 1.0), b")).to eq(%w[a b])
  end

  it "refuses relations it cannot read" do
    expect { described_class.parse("a (>= )") }.to raise_error(ArgumentError, /a \(>= \)/)
    expect { described_class.parse("Bad_Name") }.to raise_error(ArgumentError)
  end

  it "gives nothing for an empty field" do
    expect(described_class.parse(nil)).to eq([])
    expect(described_class.parse(" ")).to eq([])
  end
end
