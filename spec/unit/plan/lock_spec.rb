# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/lock"
require "relspec/plan/lock_parser"
require "relspec/plan/lock_generator"
require "relspec/plan/target"
require "relspec/builder/build_results"

# What publish makes of the lock compile wrote (docs/abi.md, "Early
# cutoff"): a kept candidate is published at the version it kept, with
# why, and its history vouches for it with compile's debian/; a built
# candidate's history moves only now. Read back by LockParser.
RSpec.describe Relspec::Plan::Lock do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64") }
  let(:old_digest) { "a" * 64 }
  let(:new_digest) { "b" * 64 }
  let(:kept_digest) { "d" * 64 }
  let(:lock) do
    entries = %w[base/user base/app].to_h do |name|
      [name, described_class::Entry.new(decision: "build", deb: "rock-r-#{name.tr('/', '-')}", version: "1.0-2~bookworm",
                                        causes: ["depends on base/lib"], depends: ["base/lib"], debian_digest: new_digest).freeze]
    end
    version = Relspec::Debian::PackageVersion.parse("1.0-1~bookworm")
    history = Relspec::Plan::History.empty.with(target, "base/user", version, old_digest).with(target, "base/app", version, old_digest)
    described_class.new(release: "r", spec_digest: "c" * 64, ancestors: {}, packages: {},
                        targets: { "bookworm/amd64" => entries }, history: history, warnings: [], notes: [])
  end
  let(:keep) do
    Relspec::Builder::BuildResults::Cutoff.new(keeps: "1.0-1~bookworm", verdict: "keep", reason: "the interface of lib did not change",
                                               evidence: ["lib: 3 files compared with 1.0-1~bookworm, unchanged"])
  end

  def reread(lock)
    Relspec::Plan::LockParser.parse(Relspec::Plan::LockGenerator.dump(lock), file: "lock.yml", release: "r")
  end

  it "publishes a kept candidate at the version it kept, with why, and moves a built one's history" do
    published = reread(lock.published([[target, "base/user", "1.0-2~bookworm", keep, kept_digest],
                                       [target, "base/app", "1.0-2~bookworm", nil]]))
    user = published.targets["bookworm/amd64"]["base/user"]
    why = "the interface of lib did not change (lib: 3 files compared with 1.0-1~bookworm, unchanged)"
    expect([user.decision, user.version, user.kept]).to eq(["published", "1.0-1~bookworm", why])
    expect(published.history.build(target, "base/user", "1.0").to_h).to eq(revision: 1, debian_digest: kept_digest, kept: why)
    expect(user.debian_digest).to eq(kept_digest)
    expect(published.targets["bookworm/amd64"]["base/app"].decision).to eq("build")
    expect(published.history.build(target, "base/app", "1.0").to_h).to eq(revision: 2, debian_digest: new_digest, kept: nil)
    expect(user.to_decision("base/user").to_h).to include("decision" => "published", "version" => "1.0-1~bookworm")
  end

  # a kept package whose kept digest is unknown (a dependency it assumed
  # kept was built after all): published, its history left for the next
  # plan, which builds it again
  it "leaves the history of a keep without a kept digest where it was" do
    published = lock.published([[target, "base/user", "1.0-2~bookworm", keep, nil]])
    expect(published.targets["bookworm/amd64"]["base/user"].decision).to eq("published")
    expect(published.history.to_h).to eq(lock.history.to_h)
  end

  it "leaves alone an outcome of another version than the locked build, and a package it does not build" do
    published = lock.published([[target, "base/user", "1.0-3~bookworm", keep], [target, "base/none", "1", nil]])
    expect(published.to_h).to eq(lock.to_h)
  end
end
