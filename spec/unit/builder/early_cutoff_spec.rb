# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/early_cutoff"
require "relspec/builder/build_plan"
require "relspec/builder/build_results"
require_relative "../../support/cutoff_verdicts"

# The run's side of the early cutoff: which candidates are not built, and
# the kept ones a build needs built first. The verdicts are a stand-in
# here (what Abi::InterfaceVerdicts decides has its own spec); the real
# builds are spec/relspec/builder/early_cutoff_build_spec.rb's.
RSpec.describe Relspec::Builder::EarlyCutoff do
  def entry(source, needs = [], candidate: false)
    cutoff = candidate ? Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: needs) : nil
    Relspec::Builder::BuildPlan::Entry.new(package: "base/#{source}", source: source, version: "1-2", dsc: "x.dsc",
                                           build_depends: needs, cutoff: cutoff)
  end

  # lib <- mid <- top, mid and top candidates; app needs top, not one.
  let(:entries) { [entry("lib"), entry("mid", ["lib"], candidate: true), entry("top", ["mid"], candidate: true), entry("app", ["top"])] }

  it "keeps the candidates decided keep, never the others" do
    cutoff = described_class.new(CutoffVerdicts.new(%w[mid], []), entries)
    expect(entries.map { |one| cutoff.keep?(one) }).to eq([false, true, false, false])
  end

  it "builds the kept packages a build needs first, in plan order, once, and records why" do
    verdicts = CutoffVerdicts.new(%w[mid top], [])
    cutoff = described_class.new(verdicts, entries)
    entries.each { |one| cutoff.keep?(one) }
    built = []
    threads = Array.new(2) { Thread.new { cutoff.build_kept_for(entries.last) { |kept| built << kept.source } } }
    threads.each(&:join)
    expect(built).to eq(%w[mid top])
    expect(verdicts.revoked.map(&:first)).to eq(%w[mid top])
    expect(verdicts.revoked.first.last).to eq("built after all: app is built in this run and names its new version")
    expect(cutoff.drain.map { |outcome| [outcome.entry.source, outcome.status] }).to eq([["mid", :built], ["top", :built]])
    expect(cutoff.drain).to eq([])
  end

  it "counts a keep of an earlier run, and fails the build that needs it when it cannot be built" do
    cutoff = described_class.new(CutoffVerdicts.new([], []), entries, kept: %w[top])
    expect { cutoff.build_kept_for(entries.last) { raise Relspec::BuildError, "dpkg-buildpackage failed" } }
      .to raise_error(Relspec::BuildError, "build-dependency top failed")
    expect(cutoff.drain.map { |outcome| [outcome.entry.source, outcome.status, outcome.reason] })
      .to eq([["top", :failed, "dpkg-buildpackage failed"]])
    expect { |block| cutoff.build_kept_for(entries.last, &block) }.not_to yield_control # no longer kept
  end
end
