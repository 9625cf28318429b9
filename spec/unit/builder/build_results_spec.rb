# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "fileutils"
require "relspec/builder/build_results"
require "relspec/plan/target"

RSpec.describe Relspec::Builder::BuildResults do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64") }
  let(:sha) { "a" * 64 }
  let(:good) do
    <<~YAML
      relspec_build_results: 1
      release: demo-base
      target: bookworm/amd64
      backend: sbuild
      packages:
        rock-demo-base-base-cmake:
          package: base/cmake
          version: 1.0-1~bookworm
          status: built
          duration: 12.3
          log: logs/rock-demo-base-base-cmake.log
          files:
            - { name: results/rock-demo-base-base-cmake/rock-demo-base-base-cmake_1.0-1~bookworm_amd64.deb, sha256: #{sha}, size: 10 }
        rock-demo-base-base-types:
          package: base/types
          version: 2.0-1~bookworm
          status: failed
          duration: 3.0
          log: logs/rock-demo-base-base-types.log
          reason: "dpkg-buildpackage failed (exit status 2)"
    YAML
  end

  def parse(text, release: "demo-base")
    described_class.parse(text, file: "build/demo-base/bookworm-amd64/build-results.yml", release: release, target: target)
  end

  def error_of(text, **options)
    parse(text, **options)
    raise "no error"
  rescue Relspec::InvalidInput => e
    e.message
  end

  it "reads every entry, sorted, with the built ones and their files" do
    results = parse(good)
    expect(results.entries.map(&:source)).to eq(%w[rock-demo-base-base-cmake rock-demo-base-base-types])
    expect(results.built.map(&:source)).to eq(%w[rock-demo-base-base-cmake])
    file = results.built.first.files.first
    expect([file.sha256, file.size, results.built.first.version]).to eq([sha, 10, "1.0-1~bookworm"])
  end

  {
    "an unknown status" => [["status: failed", "status: broken"], 17, 'status "broken" is not one of built, kept, failed, skipped, published'],
    "an unknown key" => [["duration: 3.0", "durations: 3.0"], 18, 'unknown key "durations"'],
    "a path leaving the target folder" => [["name: results/", "name: ../../"], 13, "is not a plain path inside the target folder"],
    "a bad digest" => [["sha256: #{'a' * 64}", "sha256: abc"], 13, "sha256 must be 64 lowercase hex digits"],
    "an invalid version" => [["version: 2.0-1~bookworm", "version: 2.0 beta"], 16, 'invalid Debian version "2.0 beta"'],
    "another format" => [["relspec_build_results: 1", "relspec_build_results: 2"], 1, "unknown format 2"],
    "another target" => [["target: bookworm/amd64", "target: bionic/amd64"], 3, 'target is "bionic/amd64", expected "bookworm/amd64"'],
    "files as an integer" => [[/ {6}- \{ name.*\n/, "      7\n"], 13, "packages.rock-demo-base-base-cmake.files must be a list of files"],
    "a file as a list" => [[/- \{ name.*\}/, "- [a, b]"], 13, "files.0 must be a mapping of name, sha256 and size"],
    "a duration as text" => [["duration: 3.0", "duration: soon"], 18, "duration must be a number of seconds"],
    "a log outside the folder" => [["log: logs/rock-demo-base-base-types.log", "log: /etc/passwd"], 19, "is not a plain path"],
    "a version as a list" => [["version: 2.0-1~bookworm", "version: [2]"], 16, "version must be text"],
    "a built package without files" => [[/ {4}files:\n.*\n/, ""], 7, "a built package lists the files it produced"]
  }.each do |what, ((from, to), line, message)|
    it "refuses #{what} at its line" do
      text = good.sub(from, to)
      expect(text).not_to eq(good)
      expect(error_of(text)).to match(%r{\Abuild/demo-base/bookworm-amd64/build-results\.yml:#{line}:\d+: error\[build-results\]: .*#{Regexp.escape(message)}})
    end
  end

  it "writes what it reads back, sorted, and tells which builds are still intact" do
    Dir.mktmpdir do |dir|
      deb = "results/a/a_1_amd64.deb"
      FileUtils.mkdir_p(File.join(dir, "results/a"))
      File.write(File.join(dir, deb), "deb bytes")
      results = described_class.load(dir, release: "demo-base", target: target)
      expect(results.entries).to be_empty
      record = described_class::Record
      results.record(record.new(source: "zz-b", package: "b", version: "2", status: "failed", duration: 1.5,
                                log: "logs/zz-b.log", reason: "boom", files: []))
      results.record(record.new(source: "aa-a", package: "a", version: "1", dsc_sha256: sha, status: "built", duration: 2,
                                log: "logs/aa-a.log", files: [described_class::Produced.of(dir, deb)]))
      results.write(backend: "host")
      again = described_class.load(dir, release: "demo-base", target: target)
      expect(again.entries.map(&:to_h)).to eq(results.entries.map(&:to_h))
      expect(again["aa-a"].dsc_sha256).to eq(sha)
      expect([again.entries.map(&:source), again.backend]).to eq([%w[aa-a zz-b], "host"])
      expect([again.built?("aa-a", "1", sha), again.built?("aa-a", "2", sha), again.built?("zz-b", "2", sha)])
        .to eq([true, false, false])
      # the same version from another source package (rewritten by compile), or not known
      expect([again.built?("aa-a", "1", "b" * 64), again.built?("aa-a", "1", nil)]).to eq([false, false])
      File.write(File.join(dir, deb), "changed!!")
      expect(again.built?("aa-a", "1", sha)).to be(false)
    end
  end

  it "keeps the early cutoff's verdict of a build with its record, and reads it back" do
    with = good.sub("    duration: 12.3\n", "    duration: 12.3\n    interface:\n      against: 1.0-1~bookworm\n      " \
                                            "verdict: changed\n      compared: 3\n      " \
                                            "changes: [\"include/a.h: differs\"]\n")
    expect(with).not_to eq(good)
    interface = parse(with)["rock-demo-base-base-cmake"].interface
    expect(interface.to_h).to eq("against" => "1.0-1~bookworm", "verdict" => "changed", "compared" => 3,
                                 "changes" => ["include/a.h: differs"])
    expect(interface.unchanged?).to be(false)
    expect(parse(with)["rock-demo-base-base-cmake"].to_h["interface"]).to eq(interface.to_h)
    expect(parse(good)["rock-demo-base-base-cmake"].interface).to be_nil
    {
      ["verdict: changed", "verdict: maybe"] => [13, 'verdict "maybe" is not one of unchanged, changed'],
      ["compared: 3", "compared: many"] => [14, "compared must be a number of files"],
      ['changes: ["include/a.h: differs"]', "changes: 4"] => [15, "interface.changes must be a list of changes"],
      ["against: 1.0-1~bookworm", "against: 1 0"] => [12, 'invalid Debian version "1 0"'],
      ["verdict: changed", "verdit: changed"] => [13, 'unknown key "verdit"'],
      ["compared: 3", "compared: 3\n      held: 1 0"] => [15, 'invalid Debian version "1 0"']
    }.each do |(from, to), (line, message)|
      text = with.sub(from, to)
      expect(text).not_to eq(with)
      expect(error_of(text)).to match(/build-results\.yml:#{line}:\d+: error\[build-results\]: .*#{Regexp.escape(message)}/)
    end
    # compared with a build the repository does not hold (issue 45): the one it holds, named
    held = parse(with.sub("compared: 3", "compared: 3\n      held: 1.0-0~bookworm"))["rock-demo-base-base-cmake"].interface
    expect(held.to_h).to eq(interface.to_h.merge("held" => "1.0-0~bookworm"))
  end

  it "keeps what the early cutoff decided for a candidate, and refuses another verdict" do
    with = good.sub("    duration: 12.3\n", "    duration: 12.3\n    cutoff: { keeps: 1.0-1~bookworm, verdict: keep, " \
                                            "reason: the interface of x did not change }\n")
    expect(with).not_to eq(good)
    cutoff = parse(with)["rock-demo-base-base-cmake"].cutoff
    expect(cutoff.to_h).to eq("keeps" => "1.0-1~bookworm", "verdict" => "keep", "reason" => "the interface of x did not change")
    expect(cutoff.keep?).to be(true)
    expect(error_of(with.sub("verdict: keep", "verdict: maybe"))).to include('verdict "maybe" is not one of keep, rebuild')
  end

  # docs/abi.md: a candidate the early cutoff kept is not built; its
  # record says so, with the keep and its evidence, and counts as done
  # for the same version and .dsc only.
  it "reads a kept record with its evidence, and refuses a kept one without a keep at its line" do
    kept = good.sub(/    status: built\n.*\n.*\n    files:\n.*\n/,
                    "    dsc_sha256: #{'b' * 64}\n    status: kept\n    cutoff:\n      keeps: 1.0-0~bookworm\n      verdict: keep\n      " \
                    "reason: the interface of x did not change\n      evidence: [\"x: 3 files compared with 1-1, unchanged\"]\n")
    expect(kept).not_to eq(good)
    results = parse(kept)
    record = results["rock-demo-base-base-cmake"]
    expect([record.kept?, record.built?, record.files]).to eq([true, false, []])
    expect(record.cutoff.summary).to eq("the interface of x did not change (x: 3 files compared with 1-1, unchanged)")
    expect(record.to_h["cutoff"]["evidence"]).to eq(["x: 3 files compared with 1-1, unchanged"])
    expect(results.kept?("rock-demo-base-base-cmake", "1.0-1~bookworm", "b" * 64)).to be(true)
    expect(results.kept?("rock-demo-base-base-cmake", "1.0-1~bookworm", "c" * 64)).to be(false) # another .dsc
    expect(results.kept?("rock-demo-base-base-cmake", "1.0-2~bookworm", "b" * 64)).to be(false)
    expect(results.built.map(&:source)).to eq([])
    expect(error_of(kept.sub("verdict: keep", "verdict: rebuild")))
      .to match(/build-results\.yml:10:\d+: error\[build-results\]: .*a kept package names the early cutoff's keep/)
    expect(error_of(kept.sub(/evidence: .*/, "evidence: [7]"))).to include("evidence must be text")
  end

  it "gives the records of the planned sources as a view and keeps the others in the file" do
    Dir.mktmpdir do |dir|
      results = described_class.load(dir, release: "demo-base", target: target)
      %w[aa-a zz-b].each do |source|
        results.record(described_class::Record.new(source: source, package: source, version: "1", status: "failed",
                                                   files: []))
      end
      view = results.within(["zz-b"])
      expect(view.entries.map(&:source)).to eq(["zz-b"])
      results.write(backend: "host")
      expect(described_class.load(dir, release: "demo-base", target: target).entries.map(&:source)).to eq(%w[aa-a zz-b])
    end
  end

  # publish takes the planned version only: a record of the version before
  # (its rebuild interrupted or not started) is not the release's
  it "gives, for publish, only the records at the planned versions" do
    Dir.mktmpdir do |dir|
      results = described_class.load(dir, release: "demo-base", target: target)
      { "aa-a" => "1-1", "zz-b" => "1-1", "mm-c" => "3-1" }.each do |source, version|
        results.record(described_class::Record.new(source: source, package: source, version: version, status: "built",
                                                   files: []))
      end
      view = results.at_versions("aa-a" => "1-1", "zz-b" => "1-2")
      expect(view.entries.map(&:source)).to eq(["aa-a"])
    end
  end

  it "refuses a dsc_sha256 that is not a SHA256, naming the line" do
    text = good.sub("  status: built\n", "  dsc_sha256: abc\n    status: built\n")
    expect { described_class.parse(text, file: "build-results.yml", release: "demo-base", target: target) }
      .to raise_error(Relspec::InvalidInput, /build-results.yml:\d+.*dsc_sha256 must be 64 lowercase hex digits/m)
  end

  it "refuses binary bytes and a list of files given as null for a built package" do
    expect(error_of("\x00\xff\xfe".b)).to include("build-results.yml")
    expect(error_of(good.sub(/ {6}- \{ name.*\n/, "").sub("files:", "files: null"))).to include("a built package lists the files")
  end

  it "refuses results of another release and broken YAML" do
    expect(error_of(good, release: "demo-child")).to include(":2:", 'release is "demo-base", expected "demo-child"')
    expect(error_of("packages: [\n")).to include("build-results.yml:")
    expect(error_of("")).to include("the file is empty or not a mapping")
  end
end
