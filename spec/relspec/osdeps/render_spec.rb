# frozen_string_literal: true

require "spec_helper"
require "relspec/plan"
require "relspec/osdeps/renderer"
require "relspec/osdeps/release_index"

# Rendered osdeps files, checked with autoproj's own OSPackageResolver.
RSpec.describe "relspec osdeps render" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-osdeps")
    @fixture = ReleaseFixture.new(@dir)
    all = %w[base/cmake base/logging base/types data/models drivers/iodrivers_base tools/legacy tools/orocos.rb]
    @fixture.repository("parent", [%w[bionic amd64], %w[bionic arm64], %w[buster amd64]], all.to_h { |n| [n, {}] })
    @fixture.spec("parent", "targets: { bionic: [amd64, arm64], buster: [amd64] }\n" \
                            "repository: { url: https://example.org/releases/parent, path: ../repos/parent, trusted: true }\n" \
                            "maintainer: Demo <demo@example.org>\n")
    @fixture.spec("child", "parent: parent\nblacklist: [{ match: base/types, reason: new API }]\n" \
                           "repository: { url: https://example.org/releases/child, path: ../repos/child, trusted: true }\n")
    run = relspec("osdeps", "specs/child.yml", chdir: @dir)
    raise run.stderr unless run.exit_code.zero?

    @amd64 = File.join(@dir, "releases", "child", "osdeps", "child-amd64.yml")
    @arm64 = File.join(@dir, "releases", "child", "osdeps", "child-arm64.yml")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  let(:rebuilt) { %w[base/types drivers/iodrivers_base tools/orocos.rb] }

  it "writes one file per architecture, keyed by distribution type and labels" do
    expect(Dir.children(File.dirname(@amd64)).sort).to eq(%w[child-amd64.yml child-arm64.yml])
    data = YAML.safe_load(File.read(@amd64))
    expect(data["base/cmake"]).to eq("ubuntu,debian" => { "18.04,bionic,beaver" => "rock-parent-base-cmake" },
                                     "debian" => { "10,buster" => "rock-parent-base-cmake" })
    expect(YAML.safe_load(File.read(@arm64))["base/cmake"].keys).to eq(["ubuntu,debian"])
  end

  it "maps inherited packages to the parent's names and rebuilt ones to the child's, as autoproj resolves them" do
    require "autoproj"
    { "bionic" => [%w[ubuntu debian], %w[18.04 bionic beaver default]],
      "buster" => [%w[debian], %w[10 buster default]] }.each do |codename, os|
      resolver = Autoproj::OSPackageResolver.load(@amd64, operating_system: os)
      DemoWorkspace::PACKAGES.each_key do |package|
        next if package == "drivers/old_driver" # excluded by the workspace
        next expect(resolver.resolve_package(package)).to(eq([])) if package == "tools/legacy" && codename == "buster"

        owner = rebuilt.include?(package) ? "child" : "parent"
        expect(resolver.resolve_package(package)).to eq([["apt-dpkg", 0, [@fixture.deb(owner, package)]]]), "#{package} on #{codename}"
      end
    end
  end

  it "resolves nothing on a distribution the release does not target" do
    require "autoproj"
    # autoproj adds "default" to the versions of every system it detects
    [[%w[ubuntu debian], %w[20.04 focal fossa default]], [%w[debian], %w[11 bullseye default]]].each do |os|
      resolver = Autoproj::OSPackageResolver.load(@amd64, operating_system: os)
      expect(resolver.resolve_package("base/cmake")).to eq([]), os.inspect
      expect(resolver.resolve_package("base/types")).to eq([]), os.inspect
    end
  end

  it "renders the same bytes again, and says nothing changed" do
    before = File.binread(@amd64)
    run = relspec("osdeps", "render", "specs/child.yml", chdir: @dir)
    expect(run.stderr).to include("unchanged releases/child/osdeps/child-amd64.yml")
    expect(File.binread(@amd64)).to eq(before)
  end

  it "lists planned packages the repository does not hold with --from-repository" do
    run = relspec("osdeps", "specs/child.yml", "--from-repository", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stderr).to include("missing from the repository: bionic/amd64 base/types (rock-child-base-types")
    expect(YAML.safe_load(File.read(@amd64)).keys).not_to include("base/types")
  ensure
    relspec("osdeps", "specs/child.yml", chdir: @dir)
  end

  it "writes the release index of the package set" do
    run = relspec("osdeps", "index", "--public-key", "https://example.org/releases/key.asc", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(YAML.safe_load(File.read(File.join(@dir, "releases", "releases.yml")))).to eq(
      "default" => { "repo_url" => "https://example.org/releases", "public_key" => "https://example.org/releases/key.asc",
                     "separate_prefixes" => true },
      "child" => { "depends_on" => "parent" }, "parent" => nil
    )
    expect(run.stderr).to eq("wrote releases/releases.yml\n")
    again = relspec("osdeps", "index", "--public-key", "https://example.org/releases/key.asc", chdir: @dir)
    expect(again.stderr).to eq("unchanged releases/releases.yml\n")
  end

  # What the rock-osdeps package set (github rock-core/rock-osdeps-package_set,
  # the one Rock users have) does with these files, restated as its contract:
  # a release's apt source is "<repo_url>/<name>" (its own repo_url, else the
  # default's), its osdeps file "<that>/osdeps/<name>-<arch>.yml"; depends_on is
  # one release name, followed recursively.
  it "writes an index the rock-osdeps package set turns into the spec's URLs and hierarchy" do
    relspec("osdeps", "index", chdir: @dir)
    index = YAML.load_file(File.join(@dir, "releases", "releases.yml"))
    release_url = lambda do |name|
      entry = index[name] || {}
      "#{entry.fetch('repo_url', index['default']['repo_url'])}/#{name}"
    end
    expect(release_url.call("parent")).to eq("https://example.org/releases/parent")
    expect(release_url.call("child")).to eq("https://example.org/releases/child")
    hierarchy = ->(name) { [name, *(index[name]&.key?("depends_on") ? hierarchy.call(index[name]["depends_on"]) : [])] }
    expect(hierarchy.call("child")).to eq(%w[child parent])
  end

  # The package set's osdeps lookup: the entry under autoproj's first
  # distribution name, else under all its names joined with ","; then the
  # labels key listing one of the system's version names (never "default").
  it "keys osdeps entries so that the rock-osdeps package set finds them for every target's OS labels" do
    lookup = lambda do |entry, names, versions|
      by_labels = entry[names.first] || entry[names.join(",")]
      by_labels&.find { |labels, _| (labels.split(",") & (versions - ["default"])).any? }&.last
    end
    data = YAML.load_file(@amd64)
    { [%w[ubuntu debian], %w[18.04 18.04.5 lts bionic beaver default]] => "bionic",
      [%w[debian], %w[10 buster default]] => "buster" }.each do |(names, versions), codename|
      data.each do |package, entry|
        owner = rebuilt.include?(package) ? "child" : "parent"
        next expect(lookup.call(entry, names, versions)).to(be_nil) if package == "tools/legacy" && codename == "buster"

        expect(lookup.call(entry, names, versions)).to eq(@fixture.deb(owner, package)), "#{package} on #{codename}"
      end
    end
    expect(data.values.map { |entry| lookup.call(entry, %w[debian], %w[12 bookworm default]) }.compact).to eq([])
  end
end
