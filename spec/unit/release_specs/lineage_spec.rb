# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/release_specs"
require "relspec/target"

# Specs written to a temporary folder and resolved as relspec reads them;
# nothing is fetched: opening a repository makes a reader, reading is lazy.
RSpec.describe Relspec::ReleaseSpec::Lineage do
  around do |example|
    Dir.mktmpdir("relspec-lineage") do |dir|
      @dir = dir
      example.run
    end
  end

  def spec(name, text)
    path = File.join(@dir, "#{name}.yml")
    File.write(path, text)
    path
  end

  def lineage_of(path)
    Relspec::ReleaseSpec.resolve(path).lineage
  end

  before do
    spec("base", <<~YAML)
      release: base
      workspace: ws
      targets: { bookworm: [amd64] }
      repository: { path: repos/base, url: http://127.0.0.1:1/base, trusted: true }
      package_prefix: rock
      parent: far
      external:
        far: { url: http://127.0.0.1:1/far, trusted: true, package_prefix: old, targets: { bookworm: [arm64] } }
    YAML
    @child = spec("child", <<~YAML)
      release: child
      parent: base
      workspace: ws
      repository: { path: repos/child, trusted: true }
      package_prefix: proj
      separate_prefixes: false
    YAML
  end

  it "lists the release itself first, then its ancestors in search order" do
    lineage = lineage_of(@child)
    expect(lineage.map(&:name)).to eq(%w[child base far])
    expect(lineage.own.name).to eq("child")
    expect(lineage.ancestors.map(&:name)).to eq(%w[base far])
  end

  it "gives each member its own prefixes, targets and declared repository" do
    child, base, far = lineage_of(@child).to_a
    expect([child.package_prefix, base.package_prefix, far.package_prefix]).to eq(%w[proj rock old])
    expect(child.prefixes.install_dir("child", "proj-x")).to eq("/opt/rock/child")
    expect(base.prefixes.install_dir("base", "rock-x")).to eq("/opt/rock/base/rock-x")
    expect(base.repository.path).to eq(File.join(@dir, "repos/base"))
    expect(far.repository.url).to eq("http://127.0.0.1:1/far")
    expect(base.location.to_s).to start_with("#{File.join(@dir, 'base.yml')}:4")
  end

  it "says which targets a member was built for (all of them when it does not say)" do
    _, base, far = lineage_of(@child).to_a
    amd64 = Relspec::Target.new("bookworm", "amd64")
    arm64 = Relspec::Target.new("bookworm", "arm64")
    expect([base.target?(amd64), base.target?(arm64)]).to eq([true, false])
    expect([far.target?(amd64), far.target?(arm64)]).to eq([false, true])
  end

  it "opens each ancestor's repository once, a member without one as nil" do
    spec("bare", "release: bare\nworkspace: ws\ntargets: { bookworm: [amd64] }\n")
    path = spec("top", "release: top\nparent: bare\nworkspace: ws\n")
    opened = lineage_of(path).opened_ancestors
    expect(opened.map(&:name)).to eq(["bare"])
    expect(opened.first.repository).to be_nil
    opened = lineage_of(@child).opened_ancestors
    expect(opened.map(&:repository)).to all(be_a(Relspec::Apt::Repository))
    expect(opened.first.target?(Relspec::Target.new("bookworm", "amd64"))).to be(true)
  end

  it "is deep-frozen" do
    lineage = lineage_of(@child)
    expect(lineage).to be_frozen
    expect(lineage.ancestors).to be_frozen
    expect(lineage.to_a).to all(be_frozen)
  end
end
