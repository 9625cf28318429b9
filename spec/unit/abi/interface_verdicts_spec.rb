# frozen_string_literal: true

require_relative "../unit_helper"
require "fileutils"
require "relspec/abi/interface_verdicts"
require "relspec/builder/build_plan"

# Which builds are compared with the one they replace; the comparison
# itself runs dpkg-deb and abidiff (spec/relspec/builder/early_cutoff_build_spec.rb).
RSpec.describe Relspec::Abi::InterfaceVerdicts, :tmpdir do
  let(:results) { Relspec::Builder::BuildResults }

  def record(version, status: "built", files: nil)
    files ||= begin
      FileUtils.mkdir_p(File.join(@dir, "results/a"))
      File.write(File.join(@dir, "results/a/a_#{version}_amd64.deb"), "deb #{version}")
      [results::Produced.of(@dir, "results/a/a_#{version}_amd64.deb")]
    end
    results::Record.new(source: "a", package: "base/a", version: version, status: status, files: files)
  end

  let(:entry) { plan_entry("a", "1-2") }

  def plan_entry(source, version, needs: [], cutoff: nil)
    Relspec::Builder::BuildPlan::Entry.new(package: "base/#{source}", source: source, version: version, dsc: "#{source}.dsc",
                                           build_depends: needs, cutoff: cutoff)
  end

  it "compares only a build of another version whose files are all there with the bytes recorded" do
    verdicts = described_class.new({}, @dir)
    expect(verdicts.comparable?(nil, entry)).to be(false) # a first build
    expect(verdicts.comparable?(record("1-2"), entry)).to be(false) # the same version, built again
    expect(verdicts.comparable?(record("1-1", status: "failed", files: []), entry)).to be(false)
    previous = record("1-1")
    expect(verdicts.comparable?(previous, entry)).to be(true)
    File.write(File.join(@dir, "results/a/a_1-1_amd64.deb"), "damaged")
    expect(verdicts.comparable?(previous, entry)).to be(false)
  end

  # A kept record lists the files of the build it keeps: the next build,
  # at the kept record's own (never built) version, is compared with them.
  it "compares with the build a kept record keeps, not with its planned version" do
    verdicts = described_class.new({}, @dir)
    files = record("1-1").files
    keep = results::Cutoff.new(keeps: "1-1", verdict: "keep", reason: "r", evidence: [])
    kept = results::Record.new(source: "a", package: "base/a", version: "1-2", status: "kept", files: files, cutoff: keep)
    expect(kept.files_version).to eq("1-1")
    expect(verdicts.comparable?(kept, entry)).to be(true) # entry: 1-2, the revision after the kept one
    without_files = results::Record.new(source: "a", package: "base/a", version: "1-2", status: "kept", files: [], cutoff: keep)
    expect(verdicts.comparable?(without_files, entry)).to be(false) # the target folder no longer had the kept build
  end

  # A Slurm job replaces the old files before relspec takes its build:
  # they are compared where Builder::Slurm::ReplacedFiles kept them.
  it "finds the replaced build's files under +replaced+ when given" do
    previous = record("1-1")
    kept = File.join(@dir, "replaced")
    FileUtils.mkdir_p(File.join(kept, "results/a"))
    FileUtils.mv(File.join(@dir, "results/a/a_1-1_amd64.deb"), File.join(kept, "results/a/a_1-1_amd64.deb"))
    expect(described_class.new({}, @dir).comparable?(previous, entry)).to be(false)
    expect(described_class.new({}, @dir, replaced: kept).comparable?(previous, entry)).to be(true)
  end

  it "decides nothing, and keeps nothing, when there is nothing to compare" do
    verdicts = described_class.of(Struct.new(:records) { def [](source) = records[source] }.new({}), [entry], @dir)
    expect(verdicts.decide(entry, [])).to be_nil
    expect(verdicts["a"]).to be_nil
  end

  # Issue 45: a.1-1 in the target folder was built and not published (the
  # candidate m names 1-0 the repository holds): the verdict says so.
  it "names the version the repository holds in a verdict against another build" do
    candidate = lambda do |held|
      plan_entry("m", "1-2", needs: ["a"], cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: ["a"],
                                                                                           against: { "a" => held }))
    end
    # no .deb (a unit test unpacks nothing): the comparison is of no files, what matters is against what
    FileUtils.mkdir_p(File.join(@dir, "results/a"))
    File.write(File.join(@dir, "results/a/a_1-1_amd64.buildinfo"), "1-1")
    previous = { "a" => record("1-1", files: [results::Produced.of(@dir, "results/a/a_1-1_amd64.buildinfo")]) }
    unpublished = described_class.new(previous, @dir, entries: [entry, candidate.call("1-0")]).decide(entry, [])
    expect(unpublished.to_h).to include("against" => "1-1", "held" => "1-0")
    expect(described_class.new(previous, @dir, entries: [entry, candidate.call("1-1")]).decide(entry, []).held).to be_nil
    expect(described_class.new(previous, @dir, entries: [entry]).decide(entry, []).held).to be_nil
  end

  # lib <- mid <- top: mid and top are candidates (only lib's new version
  # moved mid, only mid's moved top). lib was built at its planned version
  # by an earlier run, whose record holds its verdict.
  def run_with(lib_verdict, decide: true, refused: nil, against: nil)
    lib = plan_entry("lib", "1-2")
    mid = plan_entry("mid", "1-2", needs: ["lib"],
                                   cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: ["lib"], against: against))
    top = plan_entry("top", "1-2", needs: ["mid"], cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: ["mid"]))
    interface = results::Interface.new(against: "1-1", verdict: lib_verdict, compared: 2, changes: [])
    previous = { "lib" => results::Record.new(source: "lib", package: "base/lib", version: "1-2", status: "built", files: [],
                                              interface: interface) }
    verdicts = described_class.new(previous, @dir, entries: [lib, mid, top], refused: refused)
    [mid, top].each { |built| verdicts.decide(built, []) } if decide
    verdicts
  end

  it "keeps a candidate when everything its closure builds left its interface unchanged or is kept, through a chain" do
    verdicts = run_with("unchanged")
    expect(verdicts.closure("top")).to eq(%w[lib mid])
    expect(verdicts.cutoff("mid").to_h).to eq("keeps" => "1-1", "verdict" => "keep",
                                              "reason" => "the interface of lib did not change",
                                              "evidence" => ["lib: 2 files compared with 1-1, unchanged"])
    expect(verdicts.cutoff("top").to_h).to eq("keeps" => "1-1", "verdict" => "keep",
                                              "reason" => "the interface of mid did not change",
                                              "evidence" => ["lib: 2 files compared with 1-1, unchanged", "mid kept at 1-1"])
  end

  # Issue 45: lib 1-1 was built and not published (the repository holds
  # 1-0, which mid's kept build was made against), then lib 1-2 was built
  # and compared with 1-1: that verdict says nothing of what mid needs.
  it "rebuilds a candidate whose dependency was compared with another build than the one the repository holds" do
    unpublished = run_with("unchanged", against: { "lib" => "1-0" })
    expect(unpublished.cutoff("mid").to_h)
      .to eq("keeps" => "1-1", "verdict" => "rebuild",
             "reason" => "lib's new build was compared with 1-1, not with 1-0 that the repository holds " \
                         "and the kept build was made against")
    expect(unpublished.cutoff("top").verdict).to eq("rebuild") # mid is built: its interface has no verdict
    held = run_with("unchanged", against: { "lib" => "1-1" })
    expect(held.cutoff("mid").to_h).to include("verdict" => "keep", "reason" => "the interface of lib did not change")
    expect(run_with("unchanged", against: {}).cutoff("mid").verdict).to eq("keep") # a plan written before: unknown
    # a changed interface against the held build still rebuilds
    expect(run_with("changed", against: { "lib" => "1-1" }).cutoff("mid").reason).to eq("the interface of lib changed")
  end

  # The run decides a candidate before building it (#keep): its closure is
  # built then; a keep revoked names why it was built after all.
  it "decides a candidate before it is built, revokes a keep, and refuses every keep when told why" do
    verdicts = run_with("unchanged", decide: false)
    mid = verdicts.instance_variable_get(:@entries)["mid"]
    expect(verdicts.keep(verdicts.instance_variable_get(:@entries)["lib"])).to be_nil # no candidate
    expect(verdicts.keep(mid).verdict).to eq("keep")
    verdicts.revoke("mid", "built after all: top is built")
    expect(verdicts.cutoff("mid").to_h).to eq("keeps" => "1-1", "verdict" => "rebuild", "reason" => "built after all: top is built")
    verdicts.decide(mid, []) # the build that follows keeps the revoked decision
    expect(verdicts.cutoff("mid").reason).to eq("built after all: top is built")
    # a keep of an earlier run (none decided in this one) is revoked the same way
    earlier = run_with("unchanged", decide: false)
    earlier.revoke("top", "built after all: app is built")
    expect(earlier.cutoff("top").to_h).to eq("keeps" => "1-1", "verdict" => "rebuild", "reason" => "built after all: app is built")
    expect(verdicts.deciding?).to be(true)
    refused = run_with("unchanged", decide: false, refused: "--rebuild-dependents: every candidate is built")
    expect(refused.deciding?).to be(false)
    expect(refused.keep(refused.instance_variable_get(:@entries)["mid"]).to_h)
      .to eq("keeps" => "1-1", "verdict" => "rebuild", "reason" => "--rebuild-dependents: every candidate is built")
    # a Slurm run refusing the cutoff holds no job for a decision: the build taken records the refusal
    slurm = run_with("unchanged", refused: "--rebuild-dependents: every candidate is built")
    expect(slurm.cutoff("mid").to_h).to include("verdict" => "rebuild", "reason" => "--rebuild-dependents: every candidate is built")
  end

  # A run resumed after mid was kept: mid's keep of the earlier run, at
  # its planned version, counts for top as a keep of this run would.
  it "counts a keep an earlier run made at the planned version" do
    lib = plan_entry("lib", "1-2")
    mid = plan_entry("mid", "1-2", needs: ["lib"], cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: ["lib"]))
    top = plan_entry("top", "1-2", needs: ["mid"], cutoff: Relspec::Builder::BuildPlan::Cutoff.new(keeps: "1-1", because: ["mid"]))
    interface = results::Interface.new(against: "1-1", verdict: "unchanged", compared: 2, changes: [])
    keep = results::Cutoff.new(keeps: "1-1", verdict: "keep", reason: "r", evidence: [])
    previous = { "lib" => results::Record.new(source: "lib", package: "base/lib", version: "1-2", status: "built", files: [],
                                              interface: interface),
                 "mid" => results::Record.new(source: "mid", package: "base/mid", version: "1-2", status: "kept", files: [],
                                              cutoff: keep) }
    verdicts = described_class.new(previous, @dir, entries: [lib, mid, top])
    expect(verdicts.keep(top).to_h).to include("verdict" => "keep", "evidence" => ["lib: 2 files compared with 1-1, unchanged",
                                                                                   "mid kept at 1-1"])
    stale = previous.merge("mid" => results::Record.new(**previous["mid"].to_h.slice("package", "status").transform_keys(&:to_sym),
                                                        source: "mid", version: "1-1", files: [], cutoff: keep))
    expect(described_class.new(stale, @dir, entries: [lib, mid, top]).keep(top).verdict).to eq("rebuild") # another version
    # mid built in this run (its version was only planned when the keep was made): that keep no longer counts
    rebuilt = described_class.new(previous, @dir, entries: [lib, mid, top])
    rebuilt.decide(plan_entry("mid", "1-2", needs: ["lib"]), [])
    expect(rebuilt.keep(top).to_h).to include("verdict" => "rebuild", "reason" => "mid has no verdict to go by")
  end

  it "rebuilds a candidate whose closure holds a changed interface, also two steps down" do
    verdicts = run_with("changed")
    expect(verdicts.cutoff("mid").to_h).to eq("keeps" => "1-1", "verdict" => "rebuild", "reason" => "the interface of lib changed")
    # mid is rebuilt and, built for the first time here, has no verdict; lib changed anyway
    expect(verdicts.cutoff("top").verdict).to eq("rebuild")
    expect(verdicts.cutoff("lib")).to be_nil # no candidate
  end
end
