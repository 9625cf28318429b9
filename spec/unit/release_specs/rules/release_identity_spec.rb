# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/release_identity"

RSpec.describe Relspec::ReleaseSpec::Rules::ReleaseIdentity do
  def check(text, name: "child")
    findings(described_class.call(spec_file(text, name: name)))
  end

  it "accepts a valid name that matches the file name" do
    expect(check("release: master-20.06\n", name: "master-20.06")).to eq([])
  end

  it "refuses a release name that cannot become a Debian package name" do
    expect(check("release: Master_1\n", name: "Master_1")).to eq(['error release-name@1: invalid release name "Master_1"'])
  end

  it "refuses a release declared in a file of another name, and says how to fix it" do
    diagnostics = described_class.call(spec_file("\nrelease: other\n"))
    expect(findings(diagnostics)).to eq(['error file-name@2: release "other" is declared in a file named "child.yml"'])
    expect(diagnostics.first.hint).to eq("rename the file to other.yml or set `release: child`")
  end

  it "leaves a missing or non-text release to the schema" do
    expect(check("targets: { bionic: [amd64] }\n")).to eq([])
    expect(check("release: [a]\n")).to eq([])
  end
end
