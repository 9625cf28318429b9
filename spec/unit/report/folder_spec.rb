# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/report/folder"

RSpec.describe Relspec::Report::Folder do
  around do |example|
    Dir.mktmpdir("relspec-unit-report-folder") do |dir|
      @root = dir
      @dir = File.join(dir, "report")
      @outside = File.join(dir, "outside")
      FileUtils.mkdir_p(@outside)
      File.write(File.join(@outside, "precious.txt"), "mine\n")
      File.write(File.join(dir, "build.log"), "error: x\n")
      example.run
    end
  end

  let(:logs) { { "logs/bookworm-amd64/a.log" => File.join(@root, "build.log") } }
  let(:folder) { described_class.new(@dir) }

  it "writes the page and copies of the logs, and removes the copies no longer linked" do
    FileUtils.mkdir_p(File.join(@dir, "logs", "bookworm-amd64"))
    File.write(File.join(@dir, "logs", "bookworm-amd64", "old.log"), "old")
    expect(folder.write("<page>", logs, "index.html")).to eq(File.join(@dir, "index.html"))
    expect(Dir.glob("**/*", base: @dir).sort).to eq(%w[index.html logs logs/bookworm-amd64 logs/bookworm-amd64/a.log])
    expect(File.read(File.join(@dir, "logs", "bookworm-amd64", "a.log"))).to eq("error: x\n")
  end

  # Each link is refused before anything is written, and the folder it
  # leads to keeps its files.
  {
    "the folder itself" => "report",
    "logs/" => "report/logs",
    "a target's folder" => "report/logs/bookworm-amd64",
    "a target's folder no log links to any more" => "report/logs/bookworm-arm64",
    "a copy of a log" => "report/logs/bookworm-amd64/a.log"
  }.each do |what, link|
    it "refuses #{what} as a symbolic link, naming it, and touches nothing" do
      FileUtils.mkdir_p(File.dirname(File.join(@root, link)))
      File.symlink(link.end_with?(".log") ? File.join(@outside, "precious.txt") : @outside, File.join(@root, link))
      expect { folder.write("<page>", logs, "index.html") }
        .to raise_error(Relspec::Error, /\A#{File.join(@root, link)} is a symbolic link \(to #{@outside}.*\): relspec writes the report only inside #{@dir} and never through a link/)
      expect(Dir.children(@outside)).to eq(["precious.txt"])
      expect(File.read(File.join(@outside, "precious.txt"))).to eq("mine\n")
      expect(File.exist?(File.join(@dir, "index.html"))).to be(false) unless link == "report"
    end
  end
end
