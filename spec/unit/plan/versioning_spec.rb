# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/versioning"
require "relspec/plan/inventory"
require "relspec/plan/target"

# Versioning fed in memory: a History and the release repository's index as
# plain values (docs/plan.md, "Versions").
RSpec.describe Relspec::Plan::Versioning do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:upstream) { "1.0.20200101.000000" }
  let(:digest) { "d" * 64 }
  # what an index entry of the repository answers
  let(:index_entry) { Struct.new(:version) }

  def history(revision: nil, digest: nil, kept: nil)
    return Relspec::Plan::History.empty unless revision

    Relspec::Plan::History.new("bookworm/amd64" => { "pkg/a" => { upstream => Relspec::Plan::History::Build.new(
      revision: revision, debian_digest: digest, kept: kept
    ) } })
  end

  # docs/abi.md: publish recorded that the early cutoff kept revision 1 for
  # this debian/; a plan says so while the repository holds it.
  it "says why a published revision was kept, and a new debian/ goes on after it" do
    kept = history(revision: 1, digest: digest, kept: "the interface of lib did not change")
    settled = settle(history: kept, own: own("#{upstream}-1~bookworm"))
    expect([settled.version.to_s, settled.published, settled.kept])
      .to eq(["#{upstream}-1~bookworm", true, "the interface of lib did not change"])
    expect(settle(history: kept, own: own).kept).to be_nil # not held: built, nothing kept
    later = settle(history: kept, own: own("#{upstream}-1~bookworm"), digest: "e" * 64)
    expect([later.version.to_s, later.published, later.kept]).to eq(["#{upstream}-2~bookworm", false, nil])
  end

  def own(version = nil)
    Relspec::Plan::OwnRepository.new(version ? { target => { "rock-r-pkg-a" => index_entry.new(version) } } : {})
  end

  def settle(history: self.history, own: self.own, digest: self.digest)
    described_class.new(history: history, own: own)
                   .settle(target: target, package: "pkg/a", deb_name: "rock-r-pkg-a", upstream: upstream, digest: digest)
  end

  it "gives the published build an early cutoff keeps only when the history vouches for the revision the repository holds" do
    previous = lambda do |history, own|
      described_class.new(history: history, own: own)
                     .previous(target: target, package: "pkg/a", deb_name: "rock-r-pkg-a", upstream: upstream)
    end
    kept = previous.call(history(revision: 2, digest: digest), own("#{upstream}-2~bookworm"))
    expect([kept.first.to_s, kept.last]).to eq(["#{upstream}-2~bookworm", digest])
    expect(previous.call(history(revision: 3, digest: digest), own("#{upstream}-2~bookworm"))).to be_nil # not vouched
    expect(previous.call(history, own("#{upstream}-2~bookworm"))).to be_nil # no history
    expect(previous.call(history(revision: 2, digest: digest), own)).to be_nil # not published
    expect(previous.call(history(revision: 2, digest: digest), own("#{upstream}-2~bullseye"))).to be_nil
    expect(previous.call(history(revision: 2, digest: digest), own("0.9.20190101.000000-2~bookworm"))).to be_nil
  end

  it "starts a new upstream version at revision 1, not published" do
    settled = settle
    expect(settled.version.to_s).to eq("#{upstream}-1~bookworm")
    expect(settled.published).to be_falsey
  end

  it "keeps the recorded revision for the same debian/ and says it is published when the repository holds it" do
    settled = settle(history: history(revision: 3, digest: digest), own: own("#{upstream}-3~bookworm"))
    expect(settled.version.revision).to eq(3)
    expect(settled.published).to be(true)
  end

  it "is not published when the repository does not hold the recorded revision" do
    settled = settle(history: history(revision: 3, digest: digest))
    expect(settled.version.revision).to eq(3)
    expect(settled.published).to be_falsey
  end

  it "goes one revision up when debian/ changed for the same upstream version" do
    expect(settle(history: history(revision: 3, digest: "e" * 64)).version.revision).to eq(4)
  end

  it "never gives a revision the repository holds without the history vouching for it" do
    # the lock was lost: revision 1 in the repository may be other bytes
    expect(settle(own: own("#{upstream}-1~bookworm")).version.revision).to eq(2)
    # the repository is ahead of the lock
    expect(settle(history: history(revision: 2, digest: digest), own: own("#{upstream}-5~bookworm")).version.revision).to eq(6)
  end

  it "ignores what the repository holds of another upstream version or distribution" do
    expect(settle(own: own("0.9.20190101.000000-7~bookworm")).version.revision).to eq(1)
    expect(settle(own: own("#{upstream}-7~bullseye")).version.revision).to eq(1)
    expect(settle(own: own("#{upstream}-7")).version.revision).to eq(1) # not a version relspec gives
  end
end
