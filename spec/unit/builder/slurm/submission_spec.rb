# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/target"
require "relspec/builder/build_plan"
require "relspec/builder/host_backend"
require "relspec/builder/slurm/cluster"
require "relspec/builder/slurm/settings"
require "relspec/builder/slurm/run"
require "relspec/builder/slurm/submission"

# What one run submits to Slurm, and in which order. The cluster here is an
# in-memory stand-in that records sbatch's arguments: the unit layer starts
# no process; spec/relspec/builder/slurm_spec.rb runs the same code against
# a real one-node cluster.
RSpec.describe Relspec::Builder::Slurm::Submission, :tmpdir do
  # Records submissions (held), gives increasing ids, records releases,
  # dependencies set and cancellations.
  class RecordingCluster
    attr_reader :submitted, :released, :depended, :cancelled

    def initialize
      @submitted = []
      @released = []
      @depended = []
      @cancelled = []
    end

    def submit(script, options)
      @submitted << [File.basename(script), options]
      100 + @submitted.size
    end

    def release(ids)
      @released.concat(ids)
    end

    def depend(id, ids)
      @depended << [id, ids]
    end

    def cancel(ids)
      @cancelled.concat(ids)
    end
  end

  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:cluster) { RecordingCluster.new }

  def entry(source, build_depends = [])
    Relspec::Builder::BuildPlan::Entry.new(package: source, source: source, version: "1.0-1",
                                           dsc: "#{source}/#{source}_1.0-1.dsc", build_depends: build_depends)
  end

  def submission(entries)
    Relspec::Builder::BuildPlan.write(@dir, release: "r", target: target, entries: entries)
    plan = Relspec::Builder::BuildPlan.read(@dir)
    run = Relspec::Builder::Slurm::Run.new(plan, target, "host")
    FileUtils.mkdir_p(run.jobs_dir)
    described_class.new(cluster: cluster, settings: Relspec::Builder::Slurm::Settings.new({}),
                        backend: Relspec::Builder::HostBackend.new(nil), run: run, plan: plan, target: target)
  end

  def dependency(options)
    options.find { |option| option.start_with?("--dependency=") }
  end

  it "submits the chroot job, then each build after it and after every build-dependency of the run, and releases them at once" do
    entries = [entry("aa"), entry("bb", ["aa"]), entry("cc", ["bb"])]
    sub = submission(entries)
    sub.call(entries, {}, [], [])
    expect(cluster.submitted.map(&:first)).to eq(%w[chroot.sh aa.sh bb.sh cc.sh])
    expect(cluster.submitted.map { |_, options| dependency(options) })
      .to eq([nil, "--dependency=afterok:101", "--dependency=afterok:101:102", "--dependency=afterok:101:102:103"])
    expect(cluster.submitted.last.last).to include("--constraint=amd64", "--kill-on-invalid-dep=yes")
    expect(cluster.released).to eq([101, 102, 103, 104])
    expect([sub.prepare_id, sub.submitted, sub.tracked.transform_values(&:source)])
      .to eq([101, [101, 102, 103, 104], { 102 => "aa", 103 => "bb", 104 => "cc" }])
  end

  it "adopts the run's jobs still in the queue, releasing only the held ones" do
    entries = [entry("aa"), entry("bb", ["aa"])]
    sub = submission(entries)
    live = { "chroot" => Relspec::Builder::Slurm::Cluster::Job.new(id: 7, state: "RUNNING"),
             "aa" => Relspec::Builder::Slurm::Cluster::Job.new(id: 8, state: "PENDING", reason: "JobHeldUser") }
    sub.call(entries, live, [], [])
    expect(cluster.submitted.map { |script, options| [script, dependency(options)] })
      .to eq([["bb.sh", "--dependency=afterok:7:8"]])
    expect(cluster.released).to eq([8, 101])
    expect(sub.tracked).to eq(8 => entries[0], 101 => entries[1])
  end

  # The early cutoff's candidates (HeldCandidates): bb waits, held, after
  # the chroot job alone, so that cancelling it leaves no job with a
  # dependency that can never be met; cc, built, waits for bb's job.
  it "leaves a candidate's job held after the chroot job alone, and submits a kept one again after the live jobs" do
    entries = [entry("aa"), entry("bb", ["aa"]), entry("cc", ["bb"])]
    sub = submission(entries)
    held = sub.call(entries, {}, [], [], hold: ->(source) { source == "bb" })
    expect(cluster.submitted.map { |script, options| [script, dependency(options)] })
      .to eq([["chroot.sh", nil], ["aa.sh", "--dependency=afterok:101"], ["bb.sh", "--dependency=afterok:101"],
              ["cc.sh", "--dependency=afterok:101:102:103"]])
    expect(held).to eq([103])
    expect(cluster.released).to eq([101, 102, 104])
    expect(sub.closure_ids(entries[2])).to eq([102, 103])
    # bb kept, then built after all: after aa's job while it runs (the chroot job ended)
    expect(sub.resubmit(entries[1], [102, 104])).to eq(105)
    expect(dependency(cluster.submitted.last.last)).to eq("--dependency=afterok:102")
    expect(sub.closure_ids(entries[2])).to eq([102, 105])
    expect(sub.tracked[105]).to eq(entries[1])
  end

  it "leaves an adopted candidate's job held, releasing the other held ones" do
    entries = [entry("aa"), entry("bb", ["aa"])]
    sub = submission(entries)
    live = { "chroot" => Relspec::Builder::Slurm::Cluster::Job.new(id: 7, state: "RUNNING"),
             "aa" => Relspec::Builder::Slurm::Cluster::Job.new(id: 8, state: "PENDING", reason: "JobHeldUser"),
             "bb" => Relspec::Builder::Slurm::Cluster::Job.new(id: 9, state: "PENDING", reason: "JobHeldUser") }
    expect(sub.call(entries, live, [], [], hold: ->(source) { source == "bb" })).to eq([9])
    expect(cluster.submitted).to eq([])
    expect(cluster.released).to eq([8])
  end

  it "releases a candidate decided rebuild after the jobs of its closure still running" do
    entries = [entry("aa"), entry("bb", ["aa"])]
    sub = submission(entries)
    sub.call(entries, {}, [], [], hold: ->(source) { source == "bb" })
    sub.tracked.delete(102) # aa's job ended
    sub.release_decided(103, entries[1], [], prepare_live: true, held: true)
    expect(cluster.depended).to eq([[103, [101]]])
    expect(cluster.released.last).to eq(103)
  end

  # cc (a candidate decided rebuild) names bb, which an earlier run kept
  # (not in this run's submission): bb's job is submitted, and cc's held
  # job gives way to one whose script names bb's folder and waits for it
  # (Slurm keeps the script a job was submitted with).
  it "submits the kept packages a rebuilt candidate names first, and the candidate again naming them" do
    entries = [entry("aa"), entry("bb", ["aa"]), entry("cc", ["bb"])]
    sub = submission(entries)
    sub.call([entries[0], entries[2]], {}, [], [], hold: ->(source) { source == "cc" }) # 101 chroot, 102 aa, 103 cc
    first = File.read(File.join(@dir, "slurm", Dir.children(File.join(@dir, "slurm")).first, "cc.sh"))
    expect(first).not_to include("results/bb")
    sub.release_decided(103, entries[2], [entries[1]], prepare_live: false, held: true)
    expect(cluster.submitted.drop(3).map { |script, options| [script, dependency(options)] })
      .to eq([["bb.sh", "--dependency=afterok:102"], ["cc.sh", "--dependency=afterok:102:104"]])
    expect(cluster.cancelled).to eq([103])
    expect(cluster.released.last(2)).to eq([104, 105])
    expect(sub.tracked.transform_values(&:source)).to eq(102 => "aa", 104 => "bb", 105 => "cc")
    script = File.read(File.join(@dir, "slurm", Dir.children(File.join(@dir, "slurm")).first, "cc.sh"))
    expect(script).to include("#{@dir}/results/bb")
  end
end
