# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/diagnostic"
require "relspec/location"
require "relspec/plan/release_plan"
require "relspec/plan/target"

RSpec.describe Relspec::Plan::ReleasePlan do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }

  def warning(text) = Relspec::Diagnostic.warning("w", text, location: Relspec::Location.file_only("s.yml"))

  it "gives the same plan with other decisions, adding the warnings about them after its own" do
    plan = described_class.new(release: "r", targets: { target => {} }, packages: {}, release_digests: {},
                               warnings: [warning("planned")], notes: ["n"])
    settled = plan.with_targets({ target => {} }, warnings: [warning("settled")])
    expect([settled.release, settled.notes, settled.warnings.map(&:message)]).to eq(["r", ["n"], %w[planned settled]])
    expect(plan.with_targets({ target => {} }).warnings.map(&:message)).to eq(["planned"])
    expect(settled).to be_frozen
  end
end
