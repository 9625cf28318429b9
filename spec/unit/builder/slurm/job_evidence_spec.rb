# frozen_string_literal: true

require_relative "../../unit_helper"
require "fileutils"
require "relspec/target"
require "relspec/builder/build_plan"
require "relspec/builder/build_results"
require "relspec/builder/slurm/run"
require "relspec/builder/slurm/job_evidence"

# What the Slurm engine makes of a job's verified files. The dumps are a
# stand-in that writes a file (Builder::AbiDumper, which runs abidw, has
# its own spec; spec/relspec/builder/slurm_spec.rb makes real ones of a
# real job's .debs).
RSpec.describe Relspec::Builder::Slurm::JobEvidence, :tmpdir do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:entry) do
    Relspec::Builder::BuildPlan::Entry.new(package: "base/a", source: "rock-r-base-a", version: "1.0-2",
                                           dsc: "rock-r-base-a/rock-r-base-a_1.0-2.dsc", build_depends: [])
  end
  let(:run) do
    Relspec::Builder::BuildPlan.write(@dir, release: "r", target: target, entries: [entry])
    Relspec::Builder::Slurm::Run.new(Relspec::Builder::BuildPlan.read(@dir), target, "host")
  end
  # (entry, files) the verdicts were asked to decide
  let(:decided) { [] }
  let(:verdicts) { Struct.new(:decided) { def decide(entry, files) = decided << [entry.source, files] }.new(decided) }

  def deb(version, content)
    path = File.join(@dir, "results", "rock-r-base-a", "rock-r-base-a_#{version}_amd64.deb")
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, content)
    path
  end

  it "keeps the replaced build, makes the dumps beside the job's files, and has the build decided" do
    deb("1.0-1", "old")
    old = Relspec::Builder::BuildResults::Record.new(
      source: "rock-r-base-a", package: "base/a", version: "1.0-1", status: "built",
      files: [Relspec::Builder::BuildResults::Produced.of(@dir, "results/rock-r-base-a/rock-r-base-a_1.0-1_amd64.deb")]
    )
    asked = []
    dumps = lambda do |source, files, folder, log|
      asked << [source, files, log]
      FileUtils.mkdir_p(folder)
      File.write(File.join(folder, "libcut.so.1.abi.xml.gz"), "dump")
      [File.join(folder, "libcut.so.1.abi.xml.gz")]
    end
    evidence = described_class.new(run, dumps)
    evidence.keep([old])
    # the job replaced the folder
    FileUtils.rm_rf(File.join(@dir, "results", "rock-r-base-a"))
    new = deb("1.0-2", "new")
    files = evidence.take(verdicts).call(entry, [new])
    dump = File.join(@dir, "results", "rock-r-base-a", "libcut.so.1.abi.xml.gz")
    expect(files).to eq([new, dump])
    expect(File.read(dump)).to eq("dump")
    expect(asked).to eq([["rock-r-base-a", [new], File.join(@dir, "logs", "rock-r-base-a.log")]])
    expect(decided).to eq([["rock-r-base-a", [new, dump]]])
    expect(old.files.first.intact?(evidence.replaced.root)).to be(true)
    evidence.drop
    expect(Dir.children(run.jobs_dir)).to eq([])
  end
end
