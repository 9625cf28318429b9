# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/rising_upstream"
require "relspec/plan/history"
require "relspec/plan/inventory"
require "relspec/plan/target"

# A version kept rising when it moves back: an archive import's time (issue
# 46, case 13), a gem pinned lower or an older commit (issue 44's grape),
# fed the history and the repository as values.
RSpec.describe Relspec::Plan::RisingUpstream do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:index_entry) { Struct.new(:version) }

  def history(*upstreams)
    builds = upstreams.to_h { |upstream| [upstream, Relspec::Plan::History::Build.new(revision: 1, debian_digest: "d")] }
    Relspec::Plan::History.new(upstreams.empty? ? {} : { "bookworm/amd64" => { "ext/a" => builds } })
  end

  def own(version = nil)
    Relspec::Plan::OwnRepository.new(version ? { target => { "rock-r-ext-a" => index_entry.new(version) } } : {})
  end

  def rise(upstream, history: self.history, own: self.own)
    described_class.new(history: history, own: own)
                   .call(target: target, package: "ext/a", deb_name: "rock-r-ext-a", upstream: upstream)
  end

  it "keeps a first version, and one at or above the highest given before" do
    expect(rise("0.20210101.000000")).to eq(["0.20210101.000000", nil])
    expect(rise("0.20990101.000000", history: history("0.20210101.000000"))).to eq(["0.20990101.000000", nil])
    expect(rise("0.20210101.000000", history: history("0.20210101.000000"))).to eq(["0.20210101.000000", nil])
  end

  it "raises a version below the highest the history records above it, Debian's +really way, and says so" do
    version, raised = rise("0.20210101.000000", history: history("0.20210101.000000", "0.20990101.000000"))
    expect(version).to eq("0.20990101.000000+really0.20210101.000000")
    expect(raised.to_h).to eq(package: "ext/a", target: target, given: "0.20210101.000000", above: "0.20990101.000000",
                              upstream: version, import: false)
    expect(described_class.new(history: history("0.20990101.000000"), own: own)
                          .call(target: target, package: "ext/a", deb_name: "rock-r-ext-a", upstream: "0.20210101.000000", import: true)
                          .last.import).to be(true)
  end

  it "gives the same raised version again to the same archive, and raises again past a raised one" do
    raised = "0.20990101.000000+really0.20210101.000000"
    expect(rise("0.20210101.000000", history: history("0.20990101.000000", raised)).first).to eq(raised)
    expect(rise("0.20210101.000000", history: history("0.20990101.000000", raised)).last.above).to eq("0.20990101.000000")
    expect(rise("0.20500101.000000", history: history("0.20990101.000000", raised)).first)
      .to eq("#{raised}+really0.20500101.000000")
  end

  it "takes the repository's version as a witness when the history lost it (a discarded lock)" do
    expect(rise("0.20210101.000000", own: own("0.20990101.000000-3~bookworm")).first)
      .to eq("0.20990101.000000+really0.20210101.000000")
    expect(rise("0.20210101.000000", own: own("2:7.1-1")).first).to eq("0.20210101.000000") # not a version relspec made
  end
end
