# frozen_string_literal: true

require "spec_helper"
require "open3"
require "relspec/builder/slurm/job_script"

# A Slurm job's script, run by /bin/sh here as a node runs it (no cluster
# needed for what the script itself does): its files replace the previous
# build's only when the build succeeded, so a failed or cancelled rebuild
# leaves results/<source> as the record of the earlier build says.
RSpec.describe Relspec::Builder::Slurm::JobScript, :tmpdir do
  let(:final) { File.join(@dir, "results", "rock-r-a") }
  let(:staging) { File.join(@dir, "results", ".rock-r-a.partial") }
  let(:result) { File.join(@dir, "slurm", "rock-r-a.result") }

  before do
    FileUtils.mkdir_p([final, File.dirname(result)])
    File.write(File.join(final, "rock-r-a_1-1_amd64.deb"), "old")
  end

  def run_job(*steps)
    script = described_class.render(title: "test", steps: steps, work: File.join(@dir, "work"), result: result,
                                    output_dir: final, staging: staging, prefix: "results/rock-r-a")
    output, status = Open3.capture2e("sh", "-c", script)
    [output, status.exitstatus, File.readlines(result, chomp: true)]
  end

  it "puts a successful build's files in place of the previous ones and lists them in its result" do
    output, exit_status, lines = run_job("printf new > rock-r-a_1-2_amd64.deb", "printf info > rock-r-a_1-2_amd64.buildinfo")
    expect(exit_status).to eq(0), output
    expect(Dir.children(final).sort).to eq(%w[rock-r-a_1-2_amd64.buildinfo rock-r-a_1-2_amd64.deb])
    expect(File.exist?(staging)).to be(false)
    expect(lines).to include("status built", "exit 0")
    expect(lines.grep(/\Afile /).map { |line| line.split(" ", 4).last })
      .to eq(%w[results/rock-r-a/rock-r-a_1-2_amd64.buildinfo results/rock-r-a/rock-r-a_1-2_amd64.deb])
  end

  it "leaves the previous build's files where they were when the rebuild fails" do
    output, exit_status, lines = run_job("printf half > rock-r-a_1-2_amd64.deb", "exit 3")
    expect(exit_status).to eq(3), output
    expect(Dir.children(final)).to eq(["rock-r-a_1-1_amd64.deb"])
    expect(File.read(File.join(final, "rock-r-a_1-1_amd64.deb"))).to eq("old")
    expect(lines).to include("status failed", "exit 3")
    expect(lines.grep(/\Afile /)).to eq([])
  end

  it "starts from an empty staging folder, whatever a killed job left there" do
    FileUtils.mkdir_p(staging)
    File.write(File.join(staging, "rock-r-a_0-1_amd64.deb"), "stale")
    output, exit_status, = run_job("printf new > rock-r-a_1-2_amd64.deb")
    expect(exit_status).to eq(0), output
    expect(Dir.children(final)).to eq(["rock-r-a_1-2_amd64.deb"])
  end
end
