# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/lock_parser"
require "relspec/plan/lock_generator"
require "relspec/plan/target"

# LockParser fed lock text in memory: the mirror of LockGenerator, strict
# about everything else (docs/plan.md, "The lock").
RSpec.describe Relspec::Plan::LockParser do
  let(:digest) { "a" * 64 }
  let(:lock) do
    entries = {
      "base/cmake" => Relspec::Plan::Lock::Entry.new(decision: "inherit", deb: "rock-p-base-cmake", version: "1.0-1~bookworm",
                                                     from: "p").freeze,
      "base/types" => Relspec::Plan::Lock::Entry.new(decision: "build", deb: "rock-r-base-types", version: "2.0-3~bookworm",
                                                     causes: ["depends on base/logging", "blacklisted by \"base/logging\""],
                                                     depends: ["base/cmake"], debian_digest: digest).freeze
    }
    history = Relspec::Plan::History.empty.with("bookworm/amd64", "base/types",
                                                Relspec::Debian::PackageVersion.parse("2.0-3~bookworm"), digest)
    Relspec::Plan::Lock.new(release: "r", spec_digest: "b" * 64, ancestors: { "p" => { "bookworm" => "c" * 64 } },
                            packages: { "base/types" => { "url" => "https://example.org/t.git", "commit" => "1" * 40 },
                                        # an archive import: its checksum instead of a commit
                                        "external/x" => { "url" => "https://example.org/x.tar.gz", "sha256" => "e" * 64 } },
                            targets: { "bookworm/amd64" => entries }, history: history, warnings: ["w"], notes: [])
  end
  let(:text) { Relspec::Plan::LockGenerator.dump(lock) }

  def parse(text, release: "r")
    described_class.parse(text, file: "releases/r/lock.yml", release: release)
  end

  def error_of(text, release: "r")
    parse(text, release: release)
    raise "no error"
  rescue Relspec::LockError => e
    e.diagnostics.first
  end

  it "reads back exactly what the generator writes" do
    read = parse(text)
    expect(read.to_h).to eq(lock.to_h)
    expect(Relspec::Plan::LockGenerator.dump(read)).to eq(text)
    build = read.history.build(Relspec::Plan::Target.new("bookworm", "amd64"), "base/types", "2.0")
    expect([build.revision, build.debian_digest]).to eq([3, digest])
  end

  it "refuses the lock of another release" do
    expect(error_of(text, release: "other").message).to include("the lock is of release r, not other")
  end

  it "refuses an unknown key and names its line" do
    bad = text.sub("    base/types:\n      decision: build\n", "    base/types:\n      decision: build\n      colour: red\n")
    error = error_of(bad)
    expect(error.message).to include('unknown key "colour" in targets.bookworm/amd64.base/types')
    expect(error.location.line).to eq(bad.lines.index("      colour: red\n") + 1)
  end

  it "refuses a decision, digest or version it does not know" do
    expect(error_of(text.sub("decision: build", "decision: maybe")).message).to include('unknown decision "maybe"')
    expect(error_of(text.sub("debian_digest: #{digest}", "debian_digest: abc")).message)
      .to include("must be a SHA256 digest")
    expect(error_of(text.sub('version: "2.0-3~bookworm"', 'version: "not a version!"')).message)
      .to include("invalid Debian version")
  end

  it "refuses an unknown format and a revision that is not a positive number" do
    expect(error_of(text.sub("relspec_lock: 2", "relspec_lock: 9")).message).to include("unknown lock format 9")
    expect(error_of(text.sub("revision: 3", "revision: 0")).message).to include("revision must be a positive whole number")
  end

  it "turns the builds of a format 1 lock into the history" do
    format1 = <<~YAML
      relspec_lock: 1
      release: r
      spec_digest: #{'b' * 64}
      targets:
        bookworm/amd64:
          base/types:
            decision: inherit
            deb: rock-p-base-types
            version: 2.0-1~bookworm
            from: p
            last_build: { version: 2.0-4~bookworm, debian_digest: #{digest} }
    YAML
    build = parse(format1).history.build(Relspec::Plan::Target.new("bookworm", "amd64"), "base/types", "2.0")
    expect([build.revision, build.debian_digest]).to eq([4, digest])
  end

  it "refuses what is not text where text belongs, at its line" do
    numbered = text.sub("commit: \"#{'1' * 40}\"", "commit: 1234567")
    error = error_of(numbered)
    expect(error.message).to include("packages.base/types.commit must be text, not the number 1234567")
    expect(error.location.line).to eq(numbered.lines.index("    commit: 1234567\n") + 1)
    expect(error_of(text.sub('version: "2.0-3~bookworm"', "version: 2.10")).message)
      .to include("targets.bookworm/amd64.base/types.version must be text, not the number 2.10")
    expect(error_of(text.sub("release: r\n", "release: 12\n")).message).to include("release must be text, not the number 12")
    expect(error_of(text.sub("release: r\n", "release: true\n")).message).to include("release must be text, not true")
  end

  it "refuses a decision other than unavailable without a version" do
    expect(error_of(text.sub('version: "2.0-3~bookworm"', "version: null")).message)
      .to include("targets.bookworm/amd64.base/types: a build decision needs a version")
  end

  it "refuses a key written plain as a number, naming the key's line" do
    bad = text.sub("packages:\n", "packages:\n  7:\n    url: x\n")
    error = error_of(bad)
    expect(error.message).to include('the key 7 in packages must be text (relspec writes it quoted: "7")')
    expect([error.location.line, error.location.column]).to eq([bad.lines.index("  7:\n") + 1, 3])
    expect(parse(text.sub("packages:\n", "packages:\n  \"7\":\n    url: x\n")).packages["7"].url).to eq("x")
  end

  it "gives typed records, frozen all the way down" do
    read = parse(text)
    record = read.packages.fetch("base/types")
    expect(record).to be_a(Relspec::Plan::SourceRecord)
    expect([record.url, record.commit]).to eq(["https://example.org/t.git", "1" * 40])
    entry = read.targets.fetch("bookworm/amd64").fetch("base/types")
    [read, read.packages, record, record.url, read.targets, read.targets["bookworm/amd64"], entry, entry.causes,
     entry.causes.first, entry.depends, read.ancestors, read.ancestors["p"], read.warnings].each do |value|
      expect(value).to be_frozen
    end
  end
end
