# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/package_version"

# The gem ↔ Debian version mapping and relspec's own build versions.
RSpec.describe Relspec::Debian::PackageVersion do
  it "makes the upstream version of a source package from its manifest version and UTC commit time" do
    expect(described_class.upstream("1.2", "2020-05-04T08:00:00Z")).to eq("1.2.20200504.080000")
    expect(described_class.upstream(nil, "2020-05-04T08:00:00Z")).to eq("0.20200504.080000")
    expect(described_class.upstream("1.2", nil)).to be_nil
  end

  it "keeps only what Debian accepts of a manifest version, and 0 when it starts otherwise" do
    expect(described_class.base("v2.0 beta")).to eq("0")
    expect(described_class.base("2.0 beta/1")).to eq("2.0.beta.1")
    expect(described_class.base("3.0-rc1")).to eq("3.0.rc1")
  end

  it "maps a gem's prerelease before its release, as RubyGems orders them" do
    expect(Relspec::Debian::GemVersion.to_debian(Gem::Version.new("1.0.0.pre"))).to eq("1.0.0~pre")
    expect(Relspec::Debian::GemVersion.to_debian("4.0.2")).to eq("4.0.2")
    pre = described_class.new(Relspec::Debian::GemVersion.to_debian("1.0.0.pre"), 1, "bionic")
    expect(pre).to be < described_class.new("1.0.0", 1, "bionic")
  end

  it "formats and parses <upstream>-<revision>~<codename>, and nothing else" do
    version = described_class.parse("1.0.20200504.080000-2~bionic")
    expect([version.upstream, version.revision, version.codename]).to eq(["1.0.20200504.080000", 2, "bionic"])
    expect(version.to_s).to eq("1.0.20200504.080000-2~bionic")
    expect(version.with_revision(3).to_s).to eq("1.0.20200504.080000-3~bionic")
    expect(described_class.parse("1.0-1ubuntu1")).to be_nil
    expect(described_class.parse("1:1.0-1~bionic")).to be_nil
    expect(described_class.upstream_of("2.1-1~focal")).to eq("2.1")
  end

  it "refuses parts that would make another version than intended" do
    expect { described_class.new("a1", 1, "bionic") }.to raise_error(ArgumentError, /upstream/)
    expect { described_class.new("1.0", 0, "bionic") }.to raise_error(ArgumentError, /revision/)
    expect { described_class.new("1.0", 1, "Bionic") }.to raise_error(ArgumentError, /codename/)
  end

  it "compares and matches index versions as dpkg does" do
    version = described_class.new("1.0", 1, "bionic")
    expect(version.same_as?("1.00-1~bionic")).to be(true)
    expect(version.same_as?("1.0-1")).to be(false)
    expect(version.same_as?(nil)).to be(false)
    expect(version).to be < "1.0-2~bionic"
    expect(version).to eql(described_class.parse("1.0-1~bionic"))
    expect({ version => 1 }.key?(described_class.parse("1.0-1~bionic"))).to be(true)
  end
end
