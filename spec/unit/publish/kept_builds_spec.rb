# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/publish/kept_builds"
require "relspec/publish/locked_release"
require "relspec/builder/build_results"
require "relspec/builder/build_plan"
require "relspec/plan/lock_parser"
require "relspec/plan/inventory"
require "relspec/project"
require "relspec/target"

# Publish's side of the early cutoff (docs/abi.md): a kept record is
# refused when the repository lost the version it keeps, and the lock is
# written with the kept version and why. The repository's index is an
# OwnRepository in memory here; spec/relspec/builder/early_cutoff_build_spec.rb
# publishes into a real one.
RSpec.describe Relspec::Publish::KeptBuilds do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:index_entry) { Struct.new(:version) }
  let(:lock) do
    entry = Relspec::Plan::Lock::Entry.new(decision: "build", deb: "rock-r-base-user", version: "1.0-2~bookworm",
                                           causes: ["missing in all ancestors"], debian_digest: "b" * 64)
    Relspec::Plan::Lock.new(release: "r", spec_digest: "c" * 64, ancestors: {}, packages: {},
                            targets: { "bookworm/amd64" => { "base/user" => entry } }, history: Relspec::Plan::History.empty,
                            warnings: [], notes: [])
  end
  let(:results) do
    Relspec::Builder::BuildResults.parse(<<~YAML, file: "out/r/bookworm-amd64/build-results.yml", release: "r", target: target)
      relspec_build_results: 1
      release: r
      target: bookworm/amd64
      backend: host
      packages:
        rock-r-base-user: { package: base/user, version: 1.0-2~bookworm, status: kept, cutoff: { keeps: 1.0-1~bookworm, verdict: keep, reason: the interface of lib did not change } }
    YAML
  end

  def own(version)
    Relspec::Plan::OwnRepository.new(version ? { target => { "rock-r-base-user" => index_entry.new(version) } } : {})
  end

  # base/user kept, its dependency base/lib built (no candidate): the
  # kept digest of plan.yml holds
  let(:plan) do
    Relspec::Builder::BuildPlan.parse(<<~YAML, dir: "out/r/bookworm-amd64")
      release: r
      target: bookworm/amd64
      builds:
        - { package: base/lib, source: rock-r-base-lib, version: 1.0-2~bookworm, dsc: a.dsc, build_depends: [] }
        - { package: base/user, source: rock-r-base-user, version: 1.0-2~bookworm, dsc: b.dsc, build_depends: [rock-r-base-lib],
            cutoff: { keeps: 1.0-1~bookworm, because: [rock-r-base-lib], debian_digest: #{'d' * 64} } }
    YAML
  end

  def kept_builds(dir, read = results)
    described_class.new(Relspec::Publish::LockedRelease.new(lock, nil), { target => read }, { target => plan },
                        Relspec::Project.new(dir))
  end

  it "refuses a keep whose version the repository does not hold, before anything is published" do
    Dir.mktmpdir do |dir|
      kept = kept_builds(dir)
      expect { kept.check { own("1.0-1~bookworm") } }.not_to raise_error
      expect { kept.check { own(nil) } }
        .to raise_error(Relspec::PublishError, "bookworm/amd64: rock-r-base-user was kept at 1.0-1~bookworm by the early cutoff, " \
                                               "but the repository holds no version of it; build it: relspec build --rebuild-dependents")
      expect { kept.check { own("1.0-0~bookworm") } }.to raise_error(Relspec::PublishError, /holds 1\.0-0~bookworm;/)
      # nothing kept: the repository is not even read
      expect { kept_builds(dir, nil).check { raise "read" } }.not_to raise_error
    end
  end

  it "writes the lock with the kept version and why, which the parser reads back" do
    Dir.mktmpdir do |dir|
      written = kept_builds(dir).record(Struct.new(:release).new("r"))
      read = Relspec::Plan::LockParser.read(File.join(dir, "releases", "r", "lock.yml"), release: "r")
      entry = read.targets["bookworm/amd64"]["base/user"]
      expect([entry.decision, entry.version, entry.kept]).to eq(["published", "1.0-1~bookworm", "the interface of lib did not change"])
      expect(read.history.build(target, "base/user", "1.0").to_h).to eq(revision: 1, debian_digest: "d" * 64,
                                                                        kept: "the interface of lib did not change")
      expect(written.lock.to_h).to eq(read.to_h)
    end
  end

  it "vouches for no digest when a dependency the kept digest took as kept was built after all" do
    revoked = plan.entries.map do |entry|
      next entry unless entry.package == "base/lib"

      Relspec::Builder::BuildPlan::Entry.new(**entry.to_h.transform_keys(&:to_sym).except(:cutoff),
                                             cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1.0-1~bookworm", because: []))
    end
    entries = revoked.to_h { |entry| [entry.source, entry] }
    Dir.mktmpdir do |dir|
      kept = kept_builds(dir)
      expect(kept.kept_digest(plan.entries.to_h { |entry| [entry.source, entry] }, results, "rock-r-base-user")).to eq("d" * 64)
      # rock-r-base-lib has no record here: not kept
      expect(kept.kept_digest(entries, results, "rock-r-base-user")).to be_nil
    end
  end
end
