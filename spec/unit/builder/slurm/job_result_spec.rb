# frozen_string_literal: true

require_relative "../../unit_helper"
require "tmpdir"
require "fileutils"
require "digest"
require "relspec/builder/slurm/job_result"

# A job's result file read and checked as a local build's files are. The
# .deb ownership (dpkg-deb) is checked by spec/relspec/builder/slurm_spec.rb
# on a real cluster; here every case is decided before a .deb is opened.
RSpec.describe Relspec::Builder::Slurm::JobResult do
  around do |example|
    Dir.mktmpdir("relspec-job-result") do |dir|
      @dir = dir
      FileUtils.mkdir_p(File.join(dir, "results", "src"))
      example.run
    end
  end

  let(:version) { "1.0-1~bookworm" }

  def result(*files)
    path = File.join(@dir, "src.result")
    File.write(path, "relspec_job_result 1\nstatus built\nexit 0\nduration 2.5\n#{files.join}")
    described_class.read(path, @dir)
  end

  def listed(name, text: "bytes\n", write: true)
    path = File.join(@dir, name)
    File.write(path, text) if write
    "file #{Digest::SHA256.hexdigest(text)} #{text.bytesize} #{name}\n"
  end

  it "reads the status, exit status, duration and files" do
    read = result(listed("results/src/src_1.0-1~bookworm_amd64.buildinfo"))
    expect([read.built?, read.exit_status, read.duration]).to eq([true, 0, 2.5])
    expect(read.paths).to eq([File.join(@dir, "results/src/src_1.0-1~bookworm_amd64.buildinfo")])
  end

  it "refuses a built result without files" do
    expect(result.problem("src", version)).to eq("the job's result lists no file")
  end

  it "refuses a result without a .deb" do
    expect(result(listed("results/src/src_1.0-1~bookworm_amd64.changes")).problem("src", version))
      .to eq("the job's result lists no .deb")
  end

  it "refuses a file outside the package's results folder, by .. or by another folder" do
    FileUtils.mkdir_p(File.join(@dir, "results", "other"))
    ["results/src/../other/x.deb", "results/other/x.deb", "results/src/", "results/src/sub/x.deb"].each do |name|
      FileUtils.mkdir_p(File.dirname(File.join(@dir, name)))
      text = listed(name, write: !name.end_with?("/"))
      expect(result(text).problem("src", version)).to eq("#{name.inspect} is not a file of results/src/ (a job's files " \
                                                         "stay in its package's results folder)")
    end
  end

  it "refuses a missing file, a link, and other bytes than the node wrote" do
    name = "results/src/src_1.0-1~bookworm_amd64.buildinfo"
    expect(result(listed(name, write: false)).problem("src", version)).to eq("#{name} is missing")
    File.symlink("/etc/hostname", File.join(@dir, name))
    expect(result(listed(name, write: false)).problem("src", version)).to eq("#{name} is missing")
    File.delete(File.join(@dir, name))
    text = listed(name)
    File.write(File.join(@dir, name), "other\n")
    expect(result(text).problem("src", version)).to start_with("#{name} is not what the job wrote")
  end

  it "refuses a .buildinfo or .changes of another source or version" do
    %w[other_1.0-1~bookworm_amd64.changes src_2.0-1~bookworm_amd64.buildinfo].each do |base|
      expect(result(listed("results/src/#{base}")).problem("src", version))
        .to eq("results/src/#{base} is not a file of src #{version}")
    end
  end
end
