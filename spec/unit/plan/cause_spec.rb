# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/cause"

RSpec.describe Relspec::Plan::Cause do
  it "writes a chain as `relspec why` and the report show it: each step under the one it explains" do
    cause = described_class.depends_on("base/types", described_class.blacklisted("base/types", "own API"))
    expect(described_class.steps(cause.chain)).to eq(["  depends on base/types", '    └ blacklisted by "base/types" (own API)'])
    expect(described_class.steps([])).to eq([])
  end
end
