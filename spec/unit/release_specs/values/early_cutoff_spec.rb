# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/values/early_cutoff"

RSpec.describe Relspec::ReleaseSpec::EarlyCutoff do
  it "is on when the spec says nothing, and off only for enabled: false" do
    expect(described_class.from(nil).to_h).to eq(enabled: true, reason: nil)
    expect(described_class.from("enabled" => true).enabled).to be(true)
    expect(described_class.from("enabled" => false, "reason" => "audit").to_h).to eq(enabled: false, reason: "audit")
    expect(described_class.from(nil)).to be_frozen
  end
end
