# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/diff/lock_view"
require "relspec/plan/lock_generator"

# A lock's text as the diff's Snapshot, in memory.
RSpec.describe Relspec::Diff::LockView do
  let(:text) do
    entry = Relspec::Plan::Lock::Entry.new(decision: "build", deb: "rock-r-a", version: "1.0-1~bookworm",
                                           causes: ["blacklisted by \"a\" (forged\nline)"])
    Relspec::Plan::LockGenerator.dump(
      Relspec::Plan::Lock.new(release: "r", spec_digest: "a" * 64, ancestors: { "p" => { "bookworm" => "b" * 64 } },
                              packages: { "a" => { "url" => "https://example.org/a.git", "commit" => "1" * 40 } },
                              targets: { "bookworm/amd64" => { "a" => entry } }, history: Relspec::Plan::History.empty,
                              warnings: [], notes: [])
    )
  end

  it "gives the lock's typed source records and its decisions, causes printable" do
    snapshot = described_class.parse(text, source: "lock.yml")
    expect(snapshot.packages.fetch("a")).to have_attributes(url: "https://example.org/a.git", commit: "1" * 40)
    decision = snapshot.targets.fetch("bookworm/amd64").fetch("a")
    expect([decision.kind, decision.version, decision.causes]).to eq(["build", "1.0-1~bookworm", ["blacklisted by \"a\" (forged\\nline)"]])
    expect([snapshot, snapshot.packages, snapshot.ancestors.fetch("p"), decision.causes]).to all(be_frozen)
  end
end
