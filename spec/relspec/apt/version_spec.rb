# frozen_string_literal: true

require "spec_helper"
require "open3"
require "relspec/apt/version"

RSpec.describe Relspec::Apt::Version do
  # Versions built from the pieces that make dpkg's comparison subtle:
  # epochs, tildes, letters against other characters, leading zeros.
  def random_version(random)
    pieces = %w[0 1 2 10 01 a b z A ~ ~~ + . rc1 ~rc1 1a 1.0 2.0~beta 00]
    epoch = random.rand(6).zero? ? "#{random.rand(3)}:" : ""
    upstream = "#{random.rand(1..3)}#{Array.new(random.rand(4)) { pieces.sample(random: random) }.join}"
    revision = random.rand(3).zero? ? "" : "-#{Array.new(random.rand(1..2)) { pieces.sample(random: random) }.join.delete('-')}"
    revision = "" if revision == "-"
    "#{epoch}#{upstream.delete('-')}#{revision}"
  end

  it "orders 1500 generated pairs exactly like dpkg --compare-versions" do
    random = Random.new(20_200_601)
    pairs = Array.new(1500) { [random_version(random), random_version(random)] }
    pairs += [%w[1.0 1.0-0], %w[1.0~rc1 1.0], %w[1:0.1 2.0], %w[1.0a 1.0+], %w[1.0-1~bionic 1.0-1~buster]]
    script = pairs.map { |a, b| "if dpkg --compare-versions '#{a}' lt '#{b}'; then echo -1; elif dpkg --compare-versions '#{a}' eq '#{b}'; then echo 0; else echo 1; fi" }.join("\n")
    output, status = Open3.capture2("bash", stdin_data: script)
    expect(status).to be_success
    expected = output.split.map(&:to_i)
    expect(expected.size).to eq(pairs.size)
    mismatches = pairs.zip(expected).reject { |(a, b), want| (described_class.new(a) <=> described_class.new(b)) == want }
    expect(mismatches).to be_empty
    expect(expected.uniq.sort).to eq([-1, 0, 1])
  end

  it "splits epoch, upstream and revision at the last hyphen" do
    version = described_class.new("2:1.0-beta-3")
    expect([version.epoch, version.upstream, version.revision]).to eq([2, "1.0-beta", "3"])
  end

  it "refuses what is not a version" do
    expect { described_class.new("") }.to raise_error(ArgumentError)
    expect { described_class.new("1.0 2") }.to raise_error(ArgumentError)
  end

  it "hashes equal versions alike, so they meet in a Hash" do
    equal = [%w[1.0 1.00], %w[1.0 1.0-0], %w[1.0 1.], %w[1a0 1a], %w[2:1.01-1 2:1.1-01]]
    equal.each do |left, right|
      a = described_class.new(left)
      b = described_class.new(right)
      expect(a).to eql(b)
      expect(a.hash).to eq(b.hash), "#{left} and #{right}"
      expect({ a => true }).to have_key(b)
    end
    expect(described_class.new("1.0~")).not_to eql(described_class.new("1.0"))
    expect(described_class.new("1a0b").hash).not_to eq(described_class.new("1ab").hash)
  end

  it "accepts only what dpkg accepts as a version" do
    %w[1.0 1:2.0-1 2.0-1-2 0.9.20200605.164500-1~bionic 1.0+dfsg~rc1].each { |text| expect(described_class.valid?(text)).to be(true), text }
    ["abc", "1.0-", "1:a", "1.0 x", "a:1.0", "1.0)", ":1.0"].each do |text|
      expect(described_class.valid?(text)).to be(false), text
    end
  end
end
