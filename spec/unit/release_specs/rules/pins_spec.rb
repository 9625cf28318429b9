# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/pins"

RSpec.describe Relspec::ReleaseSpec::Rules::Pins do
  def check(text)
    findings(described_class.call(spec_file("release: child\npins:\n#{text}")))
  end

  it "accepts one commit, tag or branch per package" do
    expect(check("  base/types: { commit: 0123abc }\n  base/cmake: { tag: v1.0 }\n  tools/x: { branch: master }\n")).to eq([])
  end

  it "refuses a pin naming two refs, at the second" do
    expect(check("  base/types:\n    tag: v1\n    branch: master\n"))
      .to eq(["error pin-ref@5: the pin of base/types sets both tag and branch"])
  end

  it "refuses a commit that is no git commit id" do
    expect(check("  base/types: { commit: HEAD~1 }\n"))
      .to eq(['error pin-commit@3: commit "HEAD~1" of base/types is not a git commit id'])
    expect(check("  base/types: { commit: 0123ABC }\n").size).to eq(1)
  end

  it "refuses a package name autoproj cannot have, at its key" do
    expect(check("  \"base types\": { tag: v1 }\n")).to eq(['error package-name@3: "base types" is not a package name'])
  end
end
