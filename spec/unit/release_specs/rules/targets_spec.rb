# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/targets"

RSpec.describe Relspec::ReleaseSpec::Rules::Targets do
  def check(text)
    findings(described_class.call(spec_file("release: child\n#{text}")))
  end

  it "accepts codenames with known architectures" do
    expect(check("targets:\n  bionic: [amd64, arm64]\n  bookworm: [amd64]\n")).to eq([])
  end

  it "refuses targets without a distribution, and a distribution without an architecture" do
    expect(check("targets: {}\n")).to eq(['error empty-targets@2: "targets" lists no distribution'])
    expect(check("targets:\n  bionic: []\n")).to eq(["error empty-targets@3: bionic lists no architecture"])
  end

  it "refuses an invalid codename at its key" do
    expect(check("targets:\n  Bionic: [amd64]\n")).to eq(['error unknown-distribution@3: invalid distribution codename "Bionic"'])
  end

  it "names Debian's name for an architecture known by another name, and refuses duplicates" do
    diagnostics = described_class.call(spec_file("release: child\ntargets:\n  bionic: [x86_64, amd64, amd64]\n"))
    expect(findings(diagnostics)).to eq([
      'error unknown-architecture@3: unknown architecture "x86_64" for bionic',
      "error duplicate-architecture@3: amd64 is listed twice for bionic"
    ])
    expect(diagnostics.find { |d| d.rule == "unknown-architecture" }.hint).to eq('Debian calls it "amd64"')
  end

  it "checks an external release's targets with the same rules (Targets.check)" do
    file = spec_file("release: child\n")
    diagnostics = described_class.check(file, %w[external old targets], { "bionic" => "amd64" })
    expect(diagnostics.map(&:message)).to eq(["the architectures of bionic must be a list, found a string"])
  end
end
