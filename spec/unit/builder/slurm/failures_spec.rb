# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/target"
require "relspec/builder/build_plan"
require "relspec/builder/slurm/cluster"
require "relspec/builder/slurm/run"
require "relspec/builder/slurm/failures"

# What failed in a Slurm run, and the words of what it causes.
RSpec.describe Relspec::Builder::Slurm::Failures, :tmpdir do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }

  def entry(source, needs = [])
    Relspec::Builder::BuildPlan::Entry.new(package: "base/#{source}", source: source, version: "1", dsc: "x.dsc",
                                           build_depends: needs)
  end

  let(:failures) do
    Relspec::Builder::BuildPlan.write(@dir, release: "r", target: target, entries: [])
    described_class.new(Relspec::Builder::Slurm::Run.new(Relspec::Builder::BuildPlan.read(@dir), target, "host"), target)
  end

  it "traces a skip back to the failure it comes from, through skipped packages" do
    failures.failed(entry("a"))
    expect(failures.root(entry("b", ["a"]))).to eq("a")
    failures.skipped(entry("b", ["a"]))
    expect(failures.root(entry("c", ["b"]))).to eq("a")
    expect(failures.root(entry("d", ["x"]))).to be_nil
    expect(failures.skip_reason("a")).to eq("build-dependency a failed")
    expect(failures.not_started).to eq("not started: the run stopped after a failed (--keep-going builds the rest)")
  end

  it "skips everything after the chroot job failed, naming it, and says why a job failed" do
    job = Relspec::Builder::Slurm::Cluster::Job.new(id: 7, state: "FAILED", exit_code: 2)
    failures.chroot(job)
    root = failures.root(entry("a"))
    expect(root).to eq("the bookworm/amd64 chroot job failed (FAILED, see #{@dir}/logs/prepare.log)")
    expect(failures.skip_reason(root)).to eq(root)
    expect(failures.reason(7, entry("a"), job, nil)).to eq("a: Slurm job 7 FAILED (exit status 2), see #{@dir}/logs/a.log")
    expect(failures.reason(7, entry("a"), nil, nil)).to eq("a: Slurm job 7 left the queue without a result, see #{@dir}/logs/a.log")
  end
end
