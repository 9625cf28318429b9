# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/gem_version"

# The gem ↔ Debian version mapping, both ways, in memory.
RSpec.describe Relspec::Debian::GemVersion do
  it "gives a prerelease a tilde, so that it sorts before its release in dpkg's order" do
    expect(described_class.to_debian("1.0.0.pre")).to eq("1.0.0~pre")
    expect(described_class.to_debian(Gem::Version.new("3.1.0"))).to eq("3.1.0")
    expect(Relspec::Apt::Version.parse("#{described_class.to_debian('1.0.0.pre')}-1"))
      .to be < Relspec::Apt::Version.parse("1.0.0-1")
  end

  it "reads a distribution's ruby-* version back as the gem version it packages" do
    expect(described_class.from_debian("1.2.0+dfsg-1")).to eq(Gem::Version.new("1.2.0"))
    expect(described_class.from_debian("1:4.0.0~ds-2")).to eq(Gem::Version.new("4.0.0"))
    expect(described_class.from_debian("1.0.0~pre-1")).to eq(Gem::Version.new("1.0.0.pre"))
    expect(described_class.from_debian("0.9.1-3ubuntu1")).to eq(Gem::Version.new("0.9.1"))
    # gone back the Debian way (a pin to an older gem, relspec's RisingUpstream): the one packaged
    expect(described_class.from_debian("3.1.1+really3.0.1-1~bookworm")).to eq(Gem::Version.new("3.0.1"))
    expect(described_class.from_debian("2.0+really1.9+dfsg-2")).to eq(Gem::Version.new("1.9"))
  end

  it "is nil for a Debian upstream that is no gem version" do
    expect(described_class.from_debian("2.0+git20200101-1")).to be_nil
  end

  it "round-trips what it writes" do
    %w[1.0.0.pre 3.0.0 2.1.0.rc1].each do |version|
      expect(described_class.from_debian("#{described_class.to_debian(version)}-1")).to eq(Gem::Version.new(version))
    end
  end
end
