# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/leave_out"

RSpec.describe Relspec::ReleaseSpec::Rules::LeaveOut do
  def check(text)
    findings(described_class.call(spec_file("release: child\nleave_out:\n#{text}")))
  end

  it "accepts entries for every target and for named codenames" do
    expect(check("  - { match: gui/app, reason: qt4 }\n  - { match: gui/viz, reason: qt4, targets: [bookworm] }\n")).to eq([])
  end

  it "refuses an entry whose targets are empty: it would leave nothing out" do
    expect(check("  - { match: gui/app, reason: qt4, targets: [] }\n"))
      .to eq(["error leave-out-target@3: the leave_out entry names no target: it would leave nothing out"])
  end

  it "refuses a target that is not a codename" do
    expect(check("  - { match: gui/app, reason: qt4, targets: [Bookworm/amd64] }\n"))
      .to eq(['error leave-out-target@3: "Bookworm/amd64" is not a distribution codename'])
  end
end
