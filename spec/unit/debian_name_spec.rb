# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/debian_name"

# Debian policy 5.6.1: the one rule every reader of Debian names uses
# (plan.yml, build-results.yml, the package set, the mirror).
RSpec.describe Relspec::DebianName do
  it "accepts names of two or more of a-z 0-9 + - . starting with a letter or digit" do
    expect(%w[rock-base-types libc6 g++ 0ad x.y].map { |name| described_class.valid?(name) }).to all(be(true))
  end

  it "refuses one character, capitals, a leading - or ., spaces, options and non-text" do
    ["a", "Abc", "-o", ".x", "a b", "a=b", "", nil, 3, "a\n"].each do |name|
      expect(described_class.valid?(name)).to be(false), name.inspect
      expect(described_class.problem(name)).to include(name.inspect, "is not a Debian package name")
    end
    expect(described_class.problem("libc6")).to be_nil
  end

  it "lets a prefix be one character, since the name goes on after it" do
    expect(described_class::PREFIX.match?("r")).to be(true)
    expect(described_class::PATTERN.match?("r")).to be(false)
  end
end
