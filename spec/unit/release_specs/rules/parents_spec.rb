# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/parents"

RSpec.describe Relspec::ReleaseSpec::Rules::Parents do
  def check(text)
    findings(described_class.call(spec_file("release: child\n#{text}")))
  end

  it "accepts one parent or a list of distinct ones, and no parent at all" do
    expect(check("parent: base\n")).to eq([])
    expect(check("parent: [base, other]\n")).to eq([])
    expect(check("")).to eq([])
  end

  it "refuses an empty list" do
    expect(check("parent: []\n")).to eq(['error empty-value@2: "parent" must not be an empty list'])
  end

  it "points at each bad entry of a list" do
    expect(check("parent:\n  - base\n  - ../../etc\n  - base\n  - { a: 1 }\n")).to eq([
      'error release-name@4: invalid parent release name "../../etc"',
      'error duplicate-parent@5: parent "base" is listed twice',
      "error wrong-type@6: a parent must be a release name, found a mapping"
    ])
  end

  it "refuses a single parent that is no release name" do
    expect(check("parent: Base\n")).to eq(['error release-name@2: invalid parent release name "Base"'])
  end
end
