# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/early_cutoff"

RSpec.describe Relspec::ReleaseSpec::Rules::EarlyCutoff do
  def check(text)
    findings(described_class.call(spec_file("release: child\n#{text}")))
  end

  it "accepts the cutoff on, and off with a reason" do
    expect(check("early_cutoff: { enabled: true }\n")).to eq([])
    expect(check("early_cutoff: { enabled: false, reason: the ABI audit }\n")).to eq([])
    expect(check("description: no cutoff key\n")).to eq([])
  end

  it "refuses the cutoff turned off without a reason, at the key's line" do
    expect(check("description: d\nearly_cutoff:\n  enabled: false\n"))
      .to eq(["error early-cutoff-reason@3: early_cutoff is turned off without a reason"])
  end
end
