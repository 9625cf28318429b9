# frozen_string_literal: true

require_relative "unit_helper"
require "tmpdir"
require "fileutils"
require "digest"
require "relspec/report"

RSpec.describe Relspec::Report do
  let(:page) { Relspec::Report::Page.new(release: "child", ancestor: nil, targets: []) }

  it "writes the page with a copy of each log it links to, and removes the logs it no longer links to" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "build.log"), "error: x\n")
      out = File.join(dir, "report")
      FileUtils.mkdir_p(File.join(out, "logs", "bookworm-amd64"))
      File.write(File.join(out, "logs", "bookworm-amd64", "old.log"), "old")
      path = described_class.write(page, { "logs/bookworm-amd64/new.log" => File.join(dir, "build.log") }, out, "html")
      expect(path).to eq(File.join(out, "index.html"))
      expect(File.read(path)).to include("<h1>Release child</h1>")
      expect(Dir.glob("**/*", base: out).sort).to eq(%w[index.html logs logs/bookworm-amd64 logs/bookworm-amd64/new.log])
      expect(File.read(File.join(out, "logs", "bookworm-amd64", "new.log"))).to eq("error: x\n")
      expect(File.read(described_class.write(page, {}, out, "json"))).to start_with("{\n  \"relspec_report\": 1,")
    end
  end

  it "refuses a format it does not know before reading anything" do
    expect { described_class.run("nowhere.yml", out: "build", format: "pdf") }
      .to raise_error(Relspec::InvalidOption, 'unknown format "pdf" (known: html, json)')
  end

  # Report.abi over a project folder: a child whose last build recorded a
  # dump, a parent whose repository publishes an ABI index (no abidiff runs
  # in either case).
  context "with the ABI verdicts of `relspec abi`" do
    around do |example|
      Dir.mktmpdir("relspec-unit-report-abi") do |dir|
        @dir = dir
        example.run
      end
    end

    before do
      FileUtils.mkdir_p(File.join(@dir, "specs"))
      head = "workspace: ../ws\ntargets: { bookworm: [amd64] }\nmaintainer: Demo <demo@example.org>\n"
      File.write(File.join(@dir, "specs", "base.yml"), "release: base\n#{head}repository: { path: ../repo }\n")
      File.write(File.join(@dir, "specs", "child.yml"), "release: child\nparent: base\n#{head}")
      target = File.join(@dir, "out", "child", "bookworm-amd64")
      FileUtils.mkdir_p(File.join(target, "results", "rock-a"))
      File.write(File.join(target, "results", "rock-a", "liba.so.abi.xml.gz"), "dump")
      File.write(File.join(target, "build-results.yml"), <<~YAML)
        relspec_build_results: 1
        release: child
        target: bookworm/amd64
        backend: host
        packages:
          rock-a:
            package: a
            version: 1.0-1~bookworm
            status: built
            files:
              - { name: results/rock-a/liba.so.abi.xml.gz, sha256: #{Digest::SHA256.hexdigest('dump')}, size: 4 }
      YAML
      Relspec::Builder::BuildPlan.write(target, release: "child", target: bookworm, entries: [
        Relspec::Builder::BuildPlan::Entry.new(package: "a", source: "rock-a", version: "1.0-1~bookworm",
                                               dsc: "rock-a/rock-a_1.0-1~bookworm.dsc", build_depends: [])
      ])
    end

    let(:bookworm) { Relspec::Target.new("bookworm", "amd64") }
    let(:abi) do
      build = Relspec::TargetBuild.read(Relspec::OutputTree.new(File.join(@dir, "out"), "child"), bookworm)
      described_class.abi(Relspec::ReleaseSpec.resolve(File.join(@dir, "specs", "child.yml")), [build])
    end

    it "gives no summary when no ancestor published a dump to compare with" do
      expect(abi).to eq({})
    end

    it "gives the reason instead of verdicts when an ancestor's index is broken, and the page still gets made" do
      FileUtils.mkdir_p(File.join(@dir, "repo", "abi", "bookworm-amd64"))
      File.write(File.join(@dir, "repo", "abi", "bookworm-amd64", "index.yml"), "relspec_abi_dumps: 9\nentries: []\n")
      expect(abi.keys).to eq(["bookworm/amd64"])
      expect(abi["bookworm/amd64"].error).to include("repo/abi/bookworm-amd64/index.yml:1:20: error[abi-index]: cannot read the ABI index: unknown format 9")
      expect(abi["bookworm/amd64"].counts).to eq({})
    end
  end
end
