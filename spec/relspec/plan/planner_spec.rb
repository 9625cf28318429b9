# frozen_string_literal: true

require "spec_helper"
require "relspec/plan"

# Plans releases against real reprepro repositories: the root's read over
# HTTP from a WEBrick server, the others from disk.
RSpec.describe "relspec plan" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-plan")
    @fixture = ReleaseFixture.new(@dir)
    root_targets = [%w[bionic amd64], %w[bionic arm64], %w[buster amd64]]
    root_packages = ReleaseFixture::LAYOUT.to_h { |name| [name, {}] }
    root_packages["base/logging"] = { commit_time: "2020-01-01T00:00:00Z" } # older than the workspace
    @server = HttpServer.new(@fixture.repository("root", root_targets, root_packages))
    @fixture.repository("mid", [%w[bionic amd64], %w[buster amd64]], { "data/models" => {}, "base/cmake" => {} })
    @fixture.spec("root", <<~YAML)
      targets: { bionic: [amd64, arm64], buster: [amd64] }
      repository: { url: "#{@server.url}", trusted: true }
    YAML
    @fixture.spec("mid", <<~YAML)
      parent: root
      targets: { bionic: [amd64], buster: [amd64] }
      repository: { path: ../repos/mid, trusted: true }
      blacklist: [{ match: data/models, reason: mid needs new models }]
    YAML
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  def plan(name, yaml)
    path = @fixture.spec(name, yaml)
    Relspec::Plan.run(File.join(@dir, path), cache_dir: nil).plan
  end

  def decisions(plan, target)
    plan.targets.fetch(Relspec::Plan::Target.parse(target)).transform_values do |decision|
      decision.inherit? ? "inherit from #{decision.ancestor}" : "#{decision.kind}: #{decision.cause}"
    end
  end

  let(:leaf) do
    plan("leaf", <<~YAML)
      parent: mid
      targets: { bionic: [amd64, arm64], buster: [amd64], focal: [amd64] }
      blacklist:
        - { match: tools/legacy, reason: by name }
        - { match: "data/*", reason: by glob }
        - { match: /^base\\/ty/, reason: by regex }
    YAML
  end

  it "inherits from the nearest ancestor and rebuilds blacklisted packages with their dependents" do
    expect(decisions(leaf, "bionic/amd64")).to eq(
      "base/cmake" => "inherit from mid",
      "base/logging" => "inherit from root",
      "base/types" => 'build: blacklisted by "/^base\/ty/" (by regex)',
      "data/models" => 'build: blacklisted by "data/*" (by glob)',
      "drivers/iodrivers_base" => 'build: depends on base/types, which is rebuilt because blacklisted by "/^base\/ty/" (by regex)',
      "tools/legacy" => 'build: blacklisted by "tools/legacy" (by name)',
      "tools/orocos.rb" => 'build: depends on base/types, which is rebuilt because blacklisted by "/^base\/ty/" (by regex)'
    )
  end

  it "names what each decision uses: ancestor names and versions, own names and versions" do
    cmake = leaf.decision(Relspec::Plan::Target.parse("bionic/amd64"), "base/cmake")
    expect([cmake.deb_name, cmake.version]).to eq(["rock-mid-base-cmake", @fixture.version("base/cmake", "bionic")])
    types = leaf.decision(Relspec::Plan::Target.parse("buster/amd64"), "base/types")
    expect([types.deb_name, types.version]).to eq(["rock-leaf-base-types", @fixture.version("base/types", "buster")])
  end

  it "takes from the grandparent what the parent lacks for a target" do
    # mid has no bionic/arm64 at all; root has
    expect(decisions(leaf, "bionic/arm64")["base/cmake"]).to eq("inherit from root")
  end

  it "builds everything on a target no ancestor has" do
    result = decisions(leaf, "focal/amd64")
    expect(result.values_at("base/cmake", "base/logging", "drivers/iodrivers_base", "tools/orocos.rb").uniq)
      .to eq(["build: no ancestor has target focal/amd64"])
    expect(result["tools/legacy"]).to eq('build: blacklisted by "tools/legacy" (by name)') # the spec's reason comes first
  end

  it "warns when two ancestors provide a package, naming the targets" do
    expect(leaf.warnings.map(&:message)).to eq([
      "base/cmake is provided by mid and root (bionic/amd64, buster/amd64); mid is nearer and wins"
    ])
  end

  it "notes drift when the workspace is newer than what an ancestor has" do
    expect(leaf.notes).to include(a_string_matching(%r{drift: base/logging is at 1\.1\.20200520\.120000 in the workspace, root has 1\.1\.20200101\.000000}))
  end

  it "chains causes through several levels of dependencies" do
    deep = plan("deep", "parent: root\nblacklist: [{ match: base/cmake, reason: new toolchain }]\n")
    orocos = deep.decision(Relspec::Plan::Target.parse("bionic/amd64"), "tools/orocos.rb")
    expect(orocos.cause.chain).to eq(["depends on base/types", "depends on base/cmake",
                                      'blacklisted by "base/cmake" (new toolchain)'])
    expect(decisions(deep, "buster/amd64").values.count { |d| d.start_with?("build") }).to eq(5)
  end

  it "rebuilds a package pinned to a commit no ancestor has, and inherits one pinned to what the ancestor has" do
    logging = @fixture.catalog.package("base/logging").vcs.commit
    cmake = @fixture.catalog.package("base/cmake").vcs.commit
    pinned = plan("pinned", "parent: root\npins:\n  base/logging: { commit: #{logging[0, 10]} }\n  base/cmake: { commit: #{cmake} }\n")
    result = decisions(pinned, "bionic/amd64")
    expect(result["base/logging"]).to eq("build: pinned to #{logging}")
    expect(result["base/cmake"]).to eq("inherit from root")
    expect(result["drivers/iodrivers_base"]).to start_with("build: depends on base/logging, which is rebuilt because pinned")
  end

  it "reports packages the release's own repository already holds as published" do
    yaml = <<~YAML
      parent: root
      blacklist: [{ match: data/models, reason: local patches }]
      repository: { path: ../repos/pub, trusted: true }
    YAML
    # the lock vouches for what was built; then the repository receives it
    Relspec::Plan.run(File.join(@dir, @fixture.spec("pub", yaml)), cache_dir: nil).write_lock
    @fixture.repository("pub", [%w[bionic amd64]], { "data/models" => {} })
    published = plan("pub", yaml)
    expect(decisions(published, "bionic/amd64")["data/models"]).to eq('published: blacklisted by "data/models" (local patches)')
    expect(decisions(published, "buster/amd64")["data/models"]).to eq('build: blacklisted by "data/models" (local patches)')
    expect(published.counts(Relspec::Plan::Target.parse("bionic/amd64"))).to eq(inherit: 6, build: 0, published: 1, system: 0,
                                                                                unavailable: 0)
  end

  # Issue 44's grape pin: reprepro skips a version lower than the one it
  # holds (and exits 0), apt never upgrades to it; a git package moved to an
  # older commit is raised above the published one, as an archive's time is.
  it "keeps a package's version above a newer one its repository holds (a commit moved back), and warns" do
    yaml = <<~YAML
      parent: root
      blacklist: [{ match: data/models, reason: local patches }]
      repository: { path: ../repos/ahead, trusted: true }
    YAML
    @fixture.repository("ahead", [%w[bionic amd64]], { "data/models" => { commit_time: "2099-01-01T00:00:00Z" } })
    held = @fixture.version("data/models", "bionic", commit_time: "2099-01-01T00:00:00Z")
    ahead = plan("ahead", yaml)
    given = Relspec::Debian::PackageVersion.of_package(@fixture.catalog.package("data/models"))
    above = Relspec::Debian::PackageVersion.parse(held).upstream
    expect(ahead.targets.fetch(Relspec::Plan::Target.parse("bionic/amd64")).fetch("data/models").version.to_s)
      .to eq("#{above}+really#{given}-1~bionic")
    expect(ahead.targets.fetch(Relspec::Plan::Target.parse("buster/amd64")).fetch("data/models").version.to_s)
      .to eq("#{given}-1~buster")
    expect(ahead.warnings.join("\n"))
      .to include("warning[version-back]: data/models: its version #{given} is below #{above}, which the release already " \
                  "gave it (bionic/amd64); versioned #{above}+really#{given}, so that apt takes it as an upgrade")
  end

  it "leaves out what a target cannot have, and says why in the lock, the reports and `why`" do
    target = Relspec::Plan::Target.parse("buster/amd64")
    expect(leaf.targets.fetch(target)).not_to have_key("tools/legacy")
    expect(leaf.unavailable.fetch(target).transform_values(&:to_s))
      .to eq("tools/legacy" => "osdep motif is nonexistent on buster")
    expect(leaf.unavailable.fetch(Relspec::Plan::Target.parse("bionic/amd64"))).to eq({})
    expect(leaf.counts(target)[:unavailable]).to eq(1)

    lock = YAML.safe_load(Relspec::Plan::LockGenerator.dump(Relspec::Plan::Lock.from_plan(leaf, "0" * 64,
                                                                                          Relspec::Plan::History.empty)))
    expect(lock.dig("targets", "buster/amd64", "tools/legacy"))
      .to eq("decision" => "unavailable", "causes" => ["osdep motif is nonexistent on buster"])
    expect(lock.dig("targets", "bionic/amd64", "tools/legacy", "decision")).to eq("build")

    text = relspec("plan", "specs/leaf.yml", chdir: @dir)
    expect(text.stdout).to include("not available on buster/amd64:\n  tools/legacy  osdep motif is nonexistent on buster")
    expect(text.stdout).to match(%r{^buster/amd64\s+\d+\s+\d+\s+\d+\s+1$})
    markdown = relspec("plan", "specs/leaf.yml", "--format", "markdown", chdir: @dir).stdout
    expect(markdown).to include("| target | inherit | build | published | unavailable |",
                                "- `tools/legacy`: osdep motif is nonexistent on buster")
    why = relspec("why", "specs/leaf.yml", "tools/legacy", chdir: @dir)
    expect(why.stdout).to include("buster/amd64: tools/legacy cannot be built there, because:\n  " \
                                  "osdep motif is nonexistent on buster\n")
    expect(why.stdout).to include("bionic/amd64: tools/legacy is built here")
  end

  it "refuses a blacklist entry that matches no package" do
    expect { plan("nomatch", "parent: root\nblacklist: [{ match: \"simulation/*\", reason: x }]\n") }
      .to raise_error(Relspec::InvalidInput, %r{blacklist entry "simulation/\*" matches no package of the workspace})
  end

  it "reads each ancestor index once per target, never once per package" do
    before = @server.requests.size
    leaf
    fetched = @server.requests.drop(before)
    expect(fetched.grep(/Packages/).sort).to eq(%w[/dists/bionic/main/binary-amd64/Packages.gz
                                                   /dists/bionic/main/binary-arm64/Packages.gz
                                                   /dists/buster/main/binary-amd64/Packages.gz])
    expect(fetched.grep(/Release/).uniq.size).to eq(fetched.grep(/Release/).size)
  end

  it "writes the same lock bytes on every run, and again when planning from its own lock" do
    path = File.join(@dir, @fixture.spec("locked", "parent: mid\nblacklist: [{ match: base/types, reason: x }]\n"))
    first = Relspec::Plan.run(path, cache_dir: nil)
    second = Relspec::Plan.run(path, cache_dir: nil)
    expect(second.lock_text).to eq(first.lock_text)
    first.write_lock
    expect(Relspec::Plan.run(path, cache_dir: nil).lock_text).to eq(File.read(first.lock_path))
    expect(first.lock_text).not_to include(@dir)
    expect(first.lock_path).to eq(File.join(@dir, "releases", "locked", "lock.yml"))
  end
end
