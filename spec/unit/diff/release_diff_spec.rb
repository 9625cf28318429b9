# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/diff"
require "relspec/diff/lock_view"

# Two locks in memory, one package's recorded source moved with every
# decision kept: the diff says so in each format.
RSpec.describe Relspec::Diff::ReleaseDiff do
  let(:digest) { "a" * 64 }

  def lock(source)
    entry = Relspec::Plan::Lock::Entry.new(decision: "build", deb: "rock-r-base-types", version: "1.0-1~bookworm",
                                           causes: ["missing in all ancestors"])
    Relspec::Plan::Lock.new(release: "r", spec_digest: digest, ancestors: {},
                            packages: { "base/types" => { "url" => "https://example.org/t.git", "commit" => "1" * 40 }.merge(source) },
                            targets: { "bookworm/amd64" => { "base/types" => entry } }, history: Relspec::Plan::History.empty,
                            warnings: [], notes: [])
  end

  def compare(source)
    # no workspace: the commit counter reads no repository
    described_class.compare(Relspec::Diff::LockView.snapshot(lock({}), source: "old.yml"),
                            Relspec::Diff::LockView.snapshot(lock(source), source: "new.yml"))
  end

  it "reports a package pointed at another repository, every decision kept, as a change" do
    diff = compare("url" => "https://evil.example.org/t.git")
    expect(diff.changed?).to be(true)
    expect(diff.sources.map(&:to_s))
      .to eq(["base/types: source url https://example.org/t.git → https://evil.example.org/t.git (no decision changed)"])
    expect(diff.to_h["sources"].first["fields"]).to eq("url" => { "old" => "https://example.org/t.git",
                                                                  "new" => "https://evil.example.org/t.git" })
    expect(Relspec::Diff.render([diff], "text")).to include("\n  base/types: source url https://example.org/t.git → ")
    expect(Relspec::Diff.render([diff], "markdown")).to include("**Sources**\n\n- base/types: source url https://example.org/t.git → ")
  end

  # docs/abi.md: the lock publish wrote after the early cutoff kept a
  # dependent, against the one before: the same version, kept, and why.
  it "shows a dependent the early cutoff kept, and why, in each format" do
    published = lambda do |kept, decision: "published", version: "1.0-1~bookworm"|
      entry = Relspec::Plan::Lock::Entry.new(decision: decision, deb: "rock-r-base-user", version: version,
                                             causes: ["missing in all ancestors"], kept: kept)
      Relspec::Diff::LockView.snapshot(Relspec::Plan::Lock.new(release: "r", spec_digest: digest, ancestors: {}, packages: {},
                                                               targets: { "bookworm/amd64" => { "base/user" => entry } },
                                                               history: Relspec::Plan::History.empty, warnings: [], notes: []),
                                       source: "lock.yml")
    end
    diff = described_class.compare(published.call(nil), published.call("the interface of base/lib did not change (x)"))
    expect(diff.changed?).to be(true)
    expect(Relspec::Diff.render([diff], "text"))
      .to include("kept (early cutoff)  base/user: ", "      kept at 1.0-1~bookworm: the interface of base/lib did not change (x)\n")
    expect(diff.to_h["targets"].first["changes"].first)
      .to include("change" => "kept", "new" => include("kept" => "the interface of base/lib did not change (x)"))
    expect(described_class.compare(published.call("same"), published.call("same")).changed?).to be(false)
    # the lock compile wrote (the candidate planned at -2) against publish's
    compiled = published.call(nil, decision: "build", version: "1.0-2~bookworm")
    expect(Relspec::Diff.render([described_class.compare(compiled, published.call("why"))], "text"))
      .to include("base/user: ", "      kept at 1.0-1~bookworm: why\n")
  end

  it "is unchanged, without a sources key, when every field is the same" do
    diff = compare({})
    expect(diff.changed?).to be(false)
    expect(diff.to_h).not_to have_key("sources")
    expect(Relspec::Diff.render([diff], "text")).to eq("")
  end

  it "is a change when a side planned instead of its out-of-date lock found the lock pointing elsewhere" do
    edited = Relspec::Diff::SourceChange.of("base/types", lock({}).packages["base/types"],
                                            lock("url" => "https://evil.example.org/t.git").packages["base/types"],
                                            decided: false, recorded_in: "releases/r/lock.yml")
    planned = Relspec::Diff::Snapshot.new(**Relspec::Diff::LockView.snapshot(lock({}), source: "specs/r.yml").to_h,
                                          stale: "releases/r/lock.yml", edited: [edited]).freeze
    diff = described_class.compare(Relspec::Diff::LockView.snapshot(lock({}), source: "HEAD:releases/r/lock.yml"), planned)
    expect([diff.changed?, diff.status]).to eq([true, "changed"])
    expect(Relspec::Diff.render([diff], "text"))
      .to eq("r: HEAD:releases/r/lock.yml → specs/r.yml (planned: releases/r/lock.yml is out of date)\n  " \
             "base/types: releases/r/lock.yml records url https://evil.example.org/t.git, the plan https://example.org/t.git\n")
    expect(diff.to_h["sources"].first["recorded_in"]).to eq("releases/r/lock.yml")
  end
end
