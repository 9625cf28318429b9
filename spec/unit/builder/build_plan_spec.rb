# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "relspec/builder/build_plan"

# plan.yml, compile's writer and build's strict reader in one class (issue
# 24): what is written reads back the same, and each damage is refused at
# its line with the field named.
RSpec.describe Relspec::Builder::BuildPlan do
  entry = described_class::Entry
  let(:entries) do
    [entry.new(package: "base/a", source: "rock-r-base-a", version: "1.0-1~bookworm", dsc: "rock-r-base-a/a.dsc", build_depends: []),
     entry.new(package: "base/b", source: "rock-r-base-b", version: "2.0-1~bookworm", dsc: "rock-r-base-b/b.dsc",
               build_depends: ["rock-r-base-a"])]
  end

  def written(entries)
    Dir.mktmpdir do |dir|
      expect(described_class.write(dir, release: "r", target: "bookworm/amd64", entries: entries)).to be(true)
      expect(described_class.write(dir, release: "r", target: "bookworm/amd64", entries: entries)).to be(false)
      return File.read(File.join(dir, "plan.yml"))
    end
  end

  def error_of(text)
    described_class.parse(text, dir: "out/r/bookworm-amd64")
    nil
  rescue Relspec::InvalidInput => e
    e.diagnostics.join("\n")
  end

  it "reads back what it writes, in order" do
    plan = described_class.parse(written(entries), dir: "out/r/bookworm-amd64")
    expect([plan.release, plan.target, plan.codename, plan.arch]).to eq(["r", "bookworm/amd64", "bookworm", "amd64"])
    expect(plan.entries.map(&:to_h)).to eq(entries.map(&:to_h))
    expect(plan.dsc_path(plan.entries.first)).to eq("out/r/bookworm-amd64/rock-r-base-a/a.dsc")
  end

  {
    "builds as a mapping" => [[/builds:\n(.|\n)*/, "builds: {a: 1}\n"], 4, "builds must be a list of builds"],
    "a build as text" => [[%r{-\n  package: base/a\n(  .*\n)*?(?=-)}, "- oops\n"], 5, "builds.0 must be a mapping"],
    "a dsc outside the folder" => [["dsc: rock-r-base-a/a.dsc", "dsc: ../../etc/passwd"], 9, "is not a plain path"],
    "a source that is no name" => [["source: rock-r-base-a\n", "source: ../x\n"], 7, 'invalid source name "../x"'],
    # Debian policy 5.6.1: two characters at least, as build-results.yml reads them
    "a one-character source" => [["source: rock-r-base-a\n", "source: a\n"], 7, 'invalid source name "a"'],
    "an invalid version" => [['"2.0-1~bookworm"', '"2.0 beta"'], 14, 'invalid Debian version "2.0 beta"'],
    "a dependency not listed before" => [["- rock-r-base-a", "- rock-r-base-z"], 17, '"rock-r-base-z" is not a source listed before'],
    "build_depends as a number" => [["build_depends: []", "build_depends: 3"], 10, "must be a list of source names"],
    "an unknown key" => [["release: r", "release: r\nextra: 1"], 3, 'unknown key "extra"']
  }.each do |what, ((from, to), line, message)|
    it "refuses #{what} at its line" do
      text = written(entries)
      damaged = text.sub(from, to)
      expect(damaged).not_to eq(text)
      expect(error_of(damaged)).to include("plan.yml:#{line}:", message)
    end
  end

  it "carries an early cutoff candidate, and refuses one that names what the build does not depend on" do
    candidate = entries.last.to_h.transform_keys(&:to_sym).merge(
      cutoff: described_class::Cutoff.new(keeps: "2.0-1~bookworm", because: ["rock-r-base-a"], debian_digest: "d" * 64)
    )
    with = [entries.first, described_class::Entry.new(**candidate)]
    text = written(with)
    plan = described_class.parse(text, dir: "out/r/bookworm-amd64")
    expect(plan.entries.last.cutoff.to_h).to eq("keeps" => "2.0-1~bookworm", "because" => ["rock-r-base-a"],
                                                "debian_digest" => "d" * 64)
    expect(plan.entries.first.cutoff).to be_nil
    expect(error_of(text.sub(/because:\n *- rock-r-base-a/, "because: [rock-r-base-c]")))
      .to include('"rock-r-base-c" is not among the build\'s build_depends')
    expect(error_of(text.sub('keeps: "2.0-1~bookworm"', "keeps: 2 0"))).to include('invalid Debian version "2 0"')
    expect(error_of(text.sub("d" * 64, "xyz"))).to include("debian_digest must be 64 lowercase hex digits")
    expect(described_class.parse(text.sub(/ *debian_digest: d+
/, ""), dir: "out").entries.last.cutoff.debian_digest).to be_nil
  end

  # Issue 45: the versions the repository holds of the candidate's
  # closure, which its kept build was made against.
  it "carries what a candidate's kept build was made against, and refuses a damaged one at its line" do
    candidate = entries.last.to_h.transform_keys(&:to_sym).merge(
      cutoff: described_class::Cutoff.new(keeps: "2.0-1~bookworm", because: ["rock-r-base-a"],
                                          against: { "rock-r-base-a" => "1.0-0~bookworm" })
    )
    text = written([entries.first, described_class::Entry.new(**candidate)])
    plan = described_class.parse(text, dir: "out/r/bookworm-amd64")
    expect(plan.entries.last.cutoff.against).to eq("rock-r-base-a" => "1.0-0~bookworm")
    expect(plan.entries.last.cutoff.to_h).to include("against" => { "rock-r-base-a" => "1.0-0~bookworm" })
    line = text.lines.index { |one| one.include?("rock-r-base-a: ") } + 1
    expect(error_of(text.sub('rock-r-base-a: "1.0-0~bookworm"', 'rock-r-base-a: "1 0"')))
      .to include("plan.yml:#{line}:", 'invalid Debian version "1 0"')
    expect(error_of(text.sub('rock-r-base-a: "1.0-0~bookworm"', '"../x": "1.0-0~bookworm"')))
      .to include("plan.yml:#{line}:", 'invalid source name "../x"')
    expect(error_of(text.sub(/against:\n *rock-r-base-a: "1.0-0~bookworm"/, "against: [rock-r-base-a]")))
      .to include("plan.yml:#{line - 1}:", "against must be a mapping")
    expect(error_of(text.sub('rock-r-base-a: "1.0-0~bookworm"', "rock-r-base-a: [1]")))
      .to include("plan.yml:#{line}:", "must be text")
    # a plan written before: unknown, read as empty
    expect(described_class.parse(text.sub(/ *against:\n.*\n/, ""), dir: "out").entries.last.cutoff.against).to eq({})
  end

  it "gives a build's closure in plan order, dependencies first, each once" do
    make = ->(source, needs) { described_class::Entry.new(package: source, source: source, version: "1", dsc: "x", build_depends: needs) }
    entries = [make.call("z", []), make.call("a", ["z"]), make.call("m", %w[a z]), make.call("top", %w[m a])]
    by_source = entries.to_h { |one| [one.source, one] }
    expect(described_class.closure(by_source, "top")).to eq(%w[z a m])
    expect(described_class.closure(by_source, "z")).to eq([])
    expect(described_class.closure(by_source, "unknown")).to eq([])
  end

  it "refuses binary bytes, an empty file and broken YAML" do
    expect(error_of("\x00\xff".b)).to include("plan.yml:1:", "invalid UTF-8")
    expect(error_of("")).to include("the file is empty or not a mapping")
    expect(error_of("builds: [\n")).to include("plan.yml:", "invalid YAML")
  end
end
