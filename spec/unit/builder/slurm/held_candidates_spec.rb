# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/builder/slurm/held_candidates"
require "relspec/builder/build_plan"
require "relspec/builder/build_results"
require_relative "../../../support/cutoff_verdicts"

# Which early cutoff candidates of a Slurm run wait for their decision,
# when they are ready, and what a decision does. The verdicts are a
# stand-in (Abi::InterfaceVerdicts has its own spec); the real cluster and
# builds are spec/relspec/builder/slurm_spec.rb's.
RSpec.describe Relspec::Builder::Slurm::HeldCandidates do
  let(:verdicts) { CutoffVerdicts.new(%w[mid top], [], true) }

  def entry(source, needs = [], candidate: false)
    cutoff = candidate ? Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: needs) : nil
    Relspec::Builder::BuildPlan::Entry.new(package: "base/#{source}", source: source, version: "1-2", dsc: "x.dsc",
                                           build_depends: needs, cutoff: cutoff)
  end

  # lib <- mid <- top (candidates); app needs top and is no candidate.
  let(:lib) { entry("lib") }
  let(:mid) { entry("mid", ["lib"], candidate: true) }
  let(:top) { entry("top", ["mid"], candidate: true) }
  let(:app) { entry("app", ["top"]) }

  def held(entries, pending: entries, kept: [], released: [], with: verdicts)
    described_class.new(with, entries, pending: pending, kept: kept, released: released)
  end

  it "holds the candidates until their closure has its outcomes, in plan order, and keeps the ones decided keep" do
    cutoff = held([lib, mid, top])
    expect([lib, mid, top].map { |one| cutoff.undecided?(one.source) }).to eq([false, true, true])
    expect(cutoff.ready([])).to eq([])
    expect(cutoff.ready(%w[lib])).to eq([mid])
    expect(cutoff.decide(mid)).to have_attributes(keep: true, revoke: [])
    expect(cutoff.undecided?("mid")).to be(false)
    expect(cutoff.ready(%w[lib mid])).to eq([top])
    expect(cutoff.decide(top)).to have_attributes(keep: true, revoke: [])
    expect(verdicts.revoked).to eq([])
  end

  it "holds nothing when the run does not decide (the cutoff refused)" do
    cutoff = held([lib, mid, top], with: CutoffVerdicts.new(%w[mid top], [], false))
    expect([mid, top].map { |one| cutoff.undecided?(one.source) }).to eq([false, false])
  end

  # app is built (no candidate) and names top's new version, which names
  # mid's: both are built, their records saying why.
  it "builds a candidate a package built in the run names, saying which" do
    cutoff = held([lib, mid, top, app])
    expect(cutoff.decide(mid)).to have_attributes(keep: false, revoke: [])
    expect(cutoff.decide(top)).to have_attributes(keep: false, revoke: [])
    expect(verdicts.revoked).to eq([["mid", "built after all: app is built in this run and names its new version"],
                                    ["top", "built after all: app is built in this run and names its new version"]])
  end

  # mid kept; top's closure changed elsewhere (its verdict: rebuild): top
  # names mid's new version, so mid is built after all, first.
  it "revokes the keeps in the closure of a candidate decided rebuild" do
    only_mid = CutoffVerdicts.new(%w[mid], [], true)
    cutoff = held([lib, mid, top], with: only_mid)
    expect(cutoff.decide(mid).keep).to be(true)
    expect(cutoff.decide(top)).to have_attributes(keep: false, revoke: [mid])
    expect(only_mid.revoked).to eq([["mid", "built after all: top is built in this run and names its new version"]])
  end

  it "revokes at the start the keeps of earlier runs that a package built now names" do
    cutoff = held([lib, mid, top, app], pending: [top, app], kept: %w[mid])
    expect(cutoff.revoked_at_start).to eq([mid])
    expect(verdicts.revoked).to eq([["mid", "built after all: app is built in this run and names its new version"]])
    expect(held([lib, mid, top], pending: [top], kept: %w[mid]).revoked_at_start).to eq([]) # top may still be kept
  end

  # An earlier relspec of the run released top's job (or it finished):
  # top is built, whatever its verdict says now.
  it "builds a candidate whose job an earlier relspec of the run released" do
    cutoff = held([lib, mid, top], released: %w[top])
    expect(cutoff.undecided?("top")).to be(true) # decided when its closure is settled, for its record
    expect(cutoff.decide(mid)).to have_attributes(keep: false)
    expect(cutoff.decide(top)).to have_attributes(keep: false)
    expect(verdicts.revoked).to eq([["mid", "built after all: top is built in this run and names its new version"],
                                    ["top", "built: an earlier relspec of this run released its job"]])
  end
end
