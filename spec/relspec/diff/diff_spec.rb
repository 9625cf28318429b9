# frozen_string_literal: true

require "spec_helper"
require "json"

# relspec diff on a real release hierarchy: the demo workspace's checkouts,
# ancestors in reprepro repositories, specs and locks in a git repository.
# Every scenario changes the working tree the way a pull request would,
# records the lock with `relspec plan --write`, and compares against HEAD.
# Golden files (spec/fixtures/diff/) hold the markdown and JSON; rewrite them
# with RELSPEC_UPDATE_GOLDEN=1 and review their diff.
RSpec.describe "relspec diff" do
  GOLDEN = File.join(CliRunner::ROOT, "spec", "fixtures", "diff")
  CHILD = DiffProject::CHILD

  before(:all) do
    @dir = Dir.mktmpdir("relspec-diff")
    @project = DiffProject.new(@dir)
    @fixture = @project.fixture
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after do
    @project.git("checkout", "--quiet", "HEAD", "--", "specs", "releases")
  end

  def publish_base(older_logging:)
    @project.publish_base(older_logging: older_logging)
  end

  def write_lock
    @project.write_lock("child")
  end

  def change_child(yaml)
    @project.spec("child", yaml)
    write_lock
  end

  def diff(*args)
    relspec("diff", "--base", "HEAD", *args, chdir: @dir)
  end

  # Markdown and JSON against their golden files; returns the text diff.
  def formats(name)
    { "md" => "markdown", "json" => "json" }.each do |extension, format|
      run = diff("--format", format)
      expect(run.stderr).to eq("")
      golden = File.join(GOLDEN, "#{name}.#{extension}")
      File.write(golden, run.stdout) if ENV["RELSPEC_UPDATE_GOLDEN"]
      expect(run.stdout).to eq(File.read(golden)), "#{format} differs from #{golden}"
    end
    JSON.parse(diff("--format", "json").stdout).tap do |document|
      expect(document["relspec_diff"]).to eq(1)
    end
    diff("--format", "text").stdout
  end

  def target(document, release, target)
    document["releases"].find { |r| r["release"] == release }["targets"].find { |t| t["target"] == target }
  end

  it "prints nothing and exits 0 with --exit-code when nothing changed" do
    run = diff("--exit-code")
    expect([run.stdout, run.exit_code]).to eq(["", 0])
    run = relspec("diff", "releases/child", "releases/child/lock.yml", "--exit-code", chdir: @dir)
    expect([run.stdout, run.stderr, run.exit_code]).to eq(["", "", 0])
  end

  it "identifies an ancestor by what it provides: re-exporting its repository changes no lock" do
    release = File.join(@dir, "repos", "base", "dists", "bionic", "Release")
    before = File.read(release)
    sleep 1.1 # a new Date: field
    publish_base(older_logging: true)
    expect(File.read(release)).not_to eq(before)
    write_lock
    expect(@project.git("status", "--porcelain", "--", "releases")).to eq("")
    expect(diff("--exit-code").exit_code).to eq(0)
  end

  it "names file and line of a lock it cannot read, without a backtrace, and exits 2 with --exit-code" do
    lock = File.join(@dir, "releases", "child", "lock.yml")
    File.write(lock, File.read(lock).sub("decision: inherit", "decision: borrow"))
    run = relspec("diff", "releases/child/lock.yml", "specs/child.yml", "--exit-code", chdir: @dir)
    expect(run.exit_code).to eq(2)
    expect(run.stderr).to match(%r{\Areleases/child/lock\.yml:\d+:\d+: error\[lock\]: cannot read the lock: unknown decision "borrow"})
    expect(run.stderr).not_to include(".rb:")
    expect(run.stdout).to eq("")
  end

  it "plans a spec given as NEW or OLD, writing nothing" do
    @project.spec("child", CHILD.sub("{ bionic: [amd64] }", "{ bionic: [amd64], buster: [amd64] }"))
    run = relspec("diff", "releases/child", "specs/child.yml", chdir: @dir)
    expect(run.stdout).to start_with("child: releases/child/lock.yml → specs/child.yml\n")
    expect(run.stdout).to match(%r{^  buster/amd64: target added, 3 rebuilt$})
    expect(run.stdout).not_to include("spec:") # a release folder's spec is not known
    expect(@project.git("status", "--porcelain", "--", "releases")).to eq("") # planning wrote nothing

    run = relspec("diff", "specs/child.yml", "specs/child.yml", "--exit-code", chdir: @dir)
    expect([run.stdout, run.exit_code]).to eq(["", 0])
  end

  it "needs two inputs, or --base" do
    run = relspec("diff", "releases/child", chdir: @dir)
    expect([run.stderr, run.exit_code]).to eq(["relspec: error: relspec diff needs OLD and NEW (lock files, release folders or specs), or --base REF\n", 1])
  end

  it "colours the text on request only" do
    change_child(CHILD + "blacklist: [{ match: base/logging, reason: logging must be rebuilt }]\n")
    expect(diff("--color").stdout).to include("\e[33minherit → build\e[0m")
    expect(diff.stdout).not_to include("\e[")
  end

  it "shows a new blacklist entry as inherit → build with its cause chain, linked to the spec change" do
    change_child(CHILD + "blacklist: [{ match: base/logging, reason: logging must be rebuilt }]\n")
    text = formats("blacklist")
    expect(text).to include("spec: blacklist entry base/logging added (logging must be rebuilt)")
    expect(text).to match(%r{inherit → build\s+base/logging: inherit rock-base-base-logging \S+ from base → build rock-child-base-logging})
    expect(text).to include('blacklisted by "base/logging" (logging must be rebuilt)')
    document = JSON.parse(diff("--format", "json").stdout)
    kinds = target(document, "child", "bionic/amd64")["changes"].to_h { |c| [c["package"], c["change"]] }
    expect(kinds["base/logging"]).to eq("inherit_to_build")
    run = diff("--exit-code")
    expect(run.exit_code).to eq(1)
    expect(diff("--fail-on-rebuilds", "0").exit_code).to eq(1)
    expect(diff("--fail-on-rebuilds", "10").exit_code).to eq(0)
  end

  it "shows a moved pin: back to what the ancestor has, so build → inherit, with the commit range" do
    change_child(CHILD.sub("{ tag: v2.0.0 }", "{ branch: master }"))
    text = formats("pin")
    expect(text).to include("spec: pin of base/types moved (tag v2.0.0 → branch master) → 3 decisions (bionic/amd64)")
    types = @fixture.builder.commit_of("base/types")
    expect(text).to include("build → inherit  base/types: build rock-child-base-types 2.0.20200302.140000-1~bionic → " \
                            "inherit rock-base-base-types 2.0.20200601.103000-1~bionic from base; " \
                            "commits fee1b02..#{types[0, 7]} (1 commit)")
    expect(text).to include("osdeps base/types: rock-child-base-types → rock-base-base-types")
  end

  it "shows a package built on both sides from other commits: old → new version, commit range and count" do
    # The pin moves to the branch head and base/types is blacklisted, so the
    # child builds it from the head commit where it built the v2.0.0 tag.
    change_child(CHILD.sub("{ tag: v2.0.0 }", "{ branch: master }") +
                 "blacklist: [{ match: base/types, reason: the child needs its own build }]\n")
    text = formats("built_version")
    builder = @fixture.builder
    head = builder.commit_of("base/types")
    tagged = builder.git(builder.source_dir("base/types"), "rev-list", "-n", "1", "v2.0.0").strip
    expect(head).not_to eq(tagged)
    expect(text).to include("base/types: build rock-child-base-types 2.0.20200302.140000-1~bionic → " \
                            "build rock-child-base-types 2.0.20200601.103000-1~bionic; " \
                            "commits #{tagged[0, 7]}..#{head[0, 7]} (1 commit)")
    change = target(JSON.parse(diff("--format", "json").stdout), "child", "bionic/amd64")["changes"]
             .find { |c| c["package"] == "base/types" }
    expect(change).to include("change" => "version", "commits" => { "from" => tagged, "to" => head, "count" => 1 })
    expect([change["old"]["version"], change["new"]["version"]])
      .to eq(%w[2.0.20200302.140000-1~bionic 2.0.20200601.103000-1~bionic])
    markdown = diff("--format", "markdown").stdout
    expect(markdown).to include("2.0.20200302.140000-1~bionic → build rock-child-base-types 2.0.20200601.103000-1~bionic; " \
                                "commits #{tagged[0, 7]}..#{head[0, 7]} (1 commit)")
  end

  it "says why a dependent of a changed package gets a new Debian revision with the same source" do
    # Same change as above: drivers/iodrivers_base and tools/orocos.rb were
    # built before (they depend on the pinned base/types) and are built again
    # from the same commit, only because base/types changed version.
    change_child(CHILD.sub("{ tag: v2.0.0 }", "{ branch: master }") +
                 "blacklist: [{ match: base/types, reason: the child needs its own build }]\n")
    moved = "base/types changed version (2.0.20200302.140000-1~bionic → 2.0.20200601.103000-1~bionic)"
    text = diff.stdout
    expect(text).to include("    version  drivers/iodrivers_base: build rock-child-drivers-iodrivers-base 1.0.20200603.091500-1~bionic → " \
                            "build rock-child-drivers-iodrivers-base 1.0.20200603.091500-2~bionic\n      " \
                            "rebuilt with the same source because #{moved}; built because depends on base/types ← " \
                            'blacklisted by "base/types" (the child needs its own build)')
    markdown = diff("--format", "markdown").stdout
    expect(markdown).to include("- 2 rebuilt because #{moved}: `drivers/iodrivers_base`, `tools/orocos.rb` (bionic/amd64)")
    expect(markdown).to include('- 1 rebuilt because base/types is blacklisted by "base/types" (the child needs its own build): `base/types`')
    changes = target(JSON.parse(diff("--format", "json").stdout), "child", "bionic/amd64")["changes"]
    expect(changes.to_h { |c| [c["package"], c["rebuilt_because"]] })
      .to eq("base/types" => nil, "drivers/iodrivers_base" => moved, "tools/orocos.rb" => moved)
  end

  it "shows an added target with everything it builds" do
    change_child(CHILD.sub("{ bionic: [amd64] }", "{ bionic: [amd64], buster: [amd64] }"))
    text = formats("target")
    expect(text).to include("spec: target buster/amd64 added")
    expect(text).to match(%r{buster/amd64: target added, 3 rebuilt})
  end

  it "shows a changed parent: what is now inherited from whom, and what must be built" do
    change_child(CHILD.sub("parent: base", "parent: other"))
    text = formats("parent")
    expect(text).to include("spec: parent changed (base → other)")
    expect(text).to include("ancestor base removed on bionic")
    expect(text).to match(%r{other ancestor\s+base/cmake: inherit rock-base-base-cmake \S+ from base → inherit rock-other-base-cmake \S+ from other})
    expect(text).to match(%r{inherit → build\s+base/logging})
  end

  it "shows an ancestor publishing a new version: which ancestor, which of its packages" do
    publish_base(older_logging: false)
    write_lock
    text = formats("ancestor")
    expect(text).to include("ancestor base changed on bionic: base/logging")
    expect(text).to match(%r{version\s+base/logging: inherit rock-base-base-logging 1\.1\.20200101\.000000-1~bionic from base → inherit rock-base-base-logging 1\.1\.20200520\.120000-1~bionic from base})
  ensure
    publish_base(older_logging: true)
  end
end
