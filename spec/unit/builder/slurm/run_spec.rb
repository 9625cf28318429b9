# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/target"
require "relspec/builder/build_plan"
require "relspec/builder/slurm/cluster"
require "relspec/builder/slurm/run"

# A Slurm run's identity: the same plan, folder and backend are the same
# run (its jobs are adopted); its jobs are told apart from other runs' by name.
RSpec.describe Relspec::Builder::Slurm::Run, :tmpdir do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:entry) do
    Relspec::Builder::BuildPlan::Entry.new(package: "base/a", source: "rock-r-base-a", version: "1.0-1",
                                           dsc: "rock-r-base-a/rock-r-base-a_1.0-1.dsc", build_depends: [])
  end

  def plan(entries = [entry])
    Relspec::Builder::BuildPlan.write(@dir, release: "r", target: target, entries: entries)
    Relspec::Builder::BuildPlan.read(@dir)
  end

  def job(id, name, state = "PENDING")
    Relspec::Builder::Slurm::Cluster::Job.new(id: id, name: name, state: state)
  end

  it "is the same run for the same plan and backend, another for another plan or backend" do
    run = described_class.new(plan, target, "host")
    expect(described_class.new(plan, target, "host").id).to eq(run.id)
    expect(described_class.new(plan, target, "sbuild").id).not_to eq(run.id)
    expect(described_class.new(plan([]), target, "host").id).not_to eq(run.id)
    expect(run.jobs_dir).to eq(File.join(@dir, "slurm", run.id))
    expect(run.job_name("rock-r-base-a")).to eq("r/bookworm-amd64/rock-r-base-a@#{run.id}")
    expect(run.result_path("chroot")).to eq(File.join(run.jobs_dir, "chroot.result"))
    expect(run.log_path("rock-r-base-a")).to eq(File.join(@dir, "logs", "rock-r-base-a.log"))
  end

  it "adopts only its own jobs still in the queue, by source" do
    run = described_class.new(plan, target, "host")
    queue = [job(7, run.job_name("rock-r-base-a"), "RUNNING"), job(5, run.job_name("chroot")),
             job(6, run.job_name("rock-r-base-b"), "COMPLETED"), job(8, "r/bookworm-amd64/rock-r-base-c@other"),
             job(9, "other/bookworm-amd64/rock-r-base-a@#{run.id}")]
    expect(run.live_jobs(queue).transform_values(&:id)).to eq("chroot" => 5, "rock-r-base-a" => 7)
    expect(run.live_jobs(queue).keys).to eq(%w[chroot rock-r-base-a])
  end
end
