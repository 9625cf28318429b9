# frozen_string_literal: true

require_relative "../unit_helper"

RSpec.describe Relspec::ReleaseSpec::PackagePattern do
  names = %w[base/types base/types_ruby simulation/gazebo simulation/models/world drivers/orogen/iodrivers_base]

  def matches(source, names)
    pattern = described_class.parse(source)
    expect(pattern).to be_a(described_class), pattern.inspect
    names.select { |name| pattern.match?(name) }
  end

  it "matches an exact name only" do
    expect(matches("base/types", names)).to eq(["base/types"])
  end

  it "keeps * inside one path segment" do
    expect(matches("simulation/*", names)).to eq(["simulation/gazebo"])
    expect(matches("base/types*", names)).to eq(%w[base/types base/types_ruby])
  end

  it "lets ** cross segments" do
    expect(matches("simulation/**", names)).to eq(%w[simulation/gazebo simulation/models/world])
    expect(matches("**/iodrivers_base", names)).to eq(["drivers/orogen/iodrivers_base"])
  end

  it "treats /.../ as a regular expression, unanchored" do
    expect(matches("/orogen/", names)).to eq(["drivers/orogen/iodrivers_base"])
    expect(matches("/^base\\/types$/", names)).to eq(["base/types"])
  end

  {
    "/a(/" => "blacklist-regex", "/^base" => "blacklist-regex", "//" => "blacklist-regex",
    "a**b" => "blacklist-glob", "a//*" => "blacklist-glob", "base/*/" => "blacklist-glob",
    "drivers/[ab]*" => "blacklist-glob", "base types" => "package-name", "base/" => "package-name"
  }.each do |source, rule|
    it "rejects #{source.inspect} (#{rule})" do
      result = described_class.parse(source)
      expect(result).to be_a(described_class::Invalid)
      expect(result.rule).to eq(rule)
    end
  end
end
