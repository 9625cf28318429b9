# frozen_string_literal: true

require_relative "../../unit_helper"
require "fileutils"
require "relspec/builder/build_results"
require "relspec/builder/slurm/replaced_files"

# The replaced builds' files, kept before a job puts its own in their place.
RSpec.describe Relspec::Builder::Slurm::ReplacedFiles, :tmpdir do
  let(:results) { Relspec::Builder::BuildResults }
  let(:root) { File.join(@dir, "slurm", "run", "replaced") }

  def built(source, content, status: "built")
    FileUtils.mkdir_p(File.join(@dir, "results", source))
    File.write(File.join(@dir, "results", source, "#{source}_1_amd64.deb"), content)
    files = [results::Produced.of(@dir, "results/#{source}/#{source}_1_amd64.deb")]
    results::Record.new(source: source, package: "base/#{source}", version: "1", status: status, files: files)
  end

  it "keeps the recorded files that are intact, under their names, and keeps them when the job replaced them" do
    a = built("a", "old a")
    failed = built("b", "old b", status: "failed")
    replaced = described_class.new(root)
    replaced.keep(@dir, [a, failed, nil])
    expect(File.read(File.join(root, "results/a/a_1_amd64.deb"))).to eq("old a")
    expect(File.exist?(File.join(root, "results/b"))).to be(false) # a failed build replaces nothing to compare with
    # the job put its files in place; a relspec run again keeps the old ones
    FileUtils.rm_rf(File.join(@dir, "results/a"))
    FileUtils.mkdir_p(File.join(@dir, "results/a"))
    File.write(File.join(@dir, "results/a/a_1_amd64.deb"), "new a")
    replaced.keep(@dir, [a])
    expect(a.files.first.intact?(root)).to be(true)
    replaced.drop
    expect(File.exist?(root)).to be(false)
  end

  it "keeps nothing of a record whose files are not there with their recorded bytes" do
    a = built("a", "old a")
    File.write(File.join(@dir, "results/a/a_1_amd64.deb"), "damaged")
    described_class.new(root).keep(@dir, [a])
    expect(File.exist?(File.join(root, "results/a/a_1_amd64.deb"))).to be(false)
  end
end
