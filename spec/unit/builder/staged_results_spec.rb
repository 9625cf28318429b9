# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/staged_results"

# A build's files replace the previous build's only when it succeeded: an
# interrupted or failed rebuild leaves results/<source> as its record says.
RSpec.describe Relspec::Builder::StagedResults, :tmpdir do
  let(:staged) { described_class.new(@dir, "rock-r-a") }
  let(:final) { File.join(@dir, "results", "rock-r-a") }

  before do
    FileUtils.mkdir_p(final)
    File.write(File.join(final, "rock-r-a_1-1_amd64.deb"), "old")
  end

  it "keeps the previous files while a build runs, and after one that never settles" do
    staging = staged.prepare
    File.write(File.join(staging, "rock-r-a_1-2_amd64.deb"), "half")
    expect(Dir.children(final)).to eq(["rock-r-a_1-1_amd64.deb"])
    again = described_class.new(@dir, "rock-r-a").prepare # the next run starts clean
    expect(Dir.children(again)).to eq([])
    expect(File.read(File.join(final, "rock-r-a_1-1_amd64.deb"))).to eq("old")
  end

  it "puts a settled build's files in place of the previous ones, with their final paths" do
    staging = staged.prepare
    FileUtils.mkdir_p(File.join(staging, "abi"))
    files = [File.join(staging, "rock-r-a_1-2_amd64.deb"), File.join(staging, "abi", "liba.so.xml.gz")]
    files.each { |file| File.write(file, "new") }
    expect(staged.settle(files)).to eq([File.join(final, "rock-r-a_1-2_amd64.deb"), File.join(final, "abi", "liba.so.xml.gz")])
    expect(Dir.children(final).sort).to eq(%w[abi rock-r-a_1-2_amd64.deb])
    expect(File.exist?(staging)).to be(false)
  end

  it "refuses a staging folder that is a link out of the target folder" do
    FileUtils.mkdir_p(File.join(@dir, "elsewhere"))
    File.symlink(File.join(@dir, "elsewhere"), File.join(@dir, "results", ".rock-r-b.partial"))
    expect { described_class.new(@dir, "rock-r-b") }.to raise_error(Relspec::BuildError, /is a symbolic link/)
  end
end
