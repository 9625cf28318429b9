# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/planner"
require "relspec/plan/distribution_packages"
require "relspec/release_specs/lineage"
require "relspec/plan/inventory"
require "relspec/plan/target"
require "relspec/catalog/release_catalog"
require "relspec/catalog/uncommitted_changes"
require "relspec/release_specs/effective"
require "relspec/release_specs/spec_file"

# The Planner fed in memory: a catalog, the ancestors' indices and the spec's
# values as plain values; no workspace, repository or network
# (docs/plan.md, "Decisions").
RSpec.describe Relspec::Plan::Planner do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  # base/cmake ← base/logging ← base/types, and tools/cli on base/types
  let(:graph) { { "base/cmake" => [], "base/logging" => ["base/cmake"], "base/types" => %w[base/logging base/cmake], "tools/cli" => ["base/types"] } }

  def package(name, dependencies)
    Relspec::Catalog::Package.new(
      name: name, package_set: "set", build_type: "cmake", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/#{name}",
      version: "1.0", dependencies: dependencies,
      vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/#{name}.git", commit: "c" * 40)
    )
  end

  def release_catalog
    catalog = Relspec::Catalog.new(packages: graph.to_h { |name, deps| [name, package(name, deps)] }, layout: graph.keys,
                                   codenames: ["bookworm"])
    Relspec::Catalog::ReleaseCatalog.new(catalog, { "bookworm" => graph.keys }, { "bookworm" => {} }, "/workspace", {})
  end

  def ancestor(name)
    prefixes = Relspec::ReleaseSpec::Prefixes.new(install_prefix: "/opt/rock", separate_prefixes: true, package_prefix: "rock")
    member = Relspec::ReleaseSpec::Lineage::Member.new(name: name, prefixes: prefixes, targets: { "bookworm" => ["amd64"] })
    Relspec::ReleaseSpec::Lineage::Opened.new(member, nil)
  end

  # +held+: ancestor name => {package => upstream version}; an ancestor
  # without an entry does not have the target at all.
  # +@uncommitted+: what a test gives as the checkouts' uncommitted changes
  def plan(held, spec = {})
    indices = held.to_h do |name, packages|
      entries = packages.to_h do |package, version|
        deb = "rock-#{name}-#{package.tr('/', '-')}"
        [deb, Relspec::Apt::PackageIndex::Entry.new(deb, "#{version}-1~bookworm").freeze]
      end
      [[name, target], Relspec::Apt::PackageIndex.new(entries)]
    end
    text = "release: r\n"
    spec_file = Relspec::ReleaseSpec::SpecFile.new("specs/r.yml", Relspec::Yaml::LocatedDocument.parse(text, file: "specs/r.yml"))
    effective = Relspec::ReleaseSpec::EffectiveSpec.new(
      { "release" => "r", "targets" => { "bookworm" => ["amd64"] }, "package_prefix" => "rock" }.merge(spec), {}
    )
    described_class.new(release_catalog: release_catalog, effective: effective, spec_file: spec_file,
                        ancestors: %w[near far].map { |name| ancestor(name) },
                        inventory: Relspec::Plan::Inventory.new(indices, {}), uncommitted: @uncommitted || {}).plan
  end

  let(:upstream) { "1.0.20200601.000000" }
  let(:everything) { graph.keys.to_h { |name| [name, upstream] } }

  def kinds(plan)
    plan.targets.fetch(target).transform_values(&:kind)
  end

  it "inherits what the nearest ancestor holds, at its version" do
    result = plan("near" => everything, "far" => everything)
    expect(kinds(result).values.uniq).to eq([:inherit])
    decision = result.decision(target, "base/types")
    expect([decision.ancestor, decision.deb_name, decision.version])
      .to eq(["near", "rock-near-base-types", "#{upstream}-1~bookworm"])
    expect(result.warnings.map(&:message).first).to include("base/cmake is provided by near and far (bookworm/amd64)")
  end

  it "takes a package the nearest ancestor lacks from the next one" do
    result = plan("near" => everything.except("tools/cli"), "far" => everything)
    expect(result.decision(target, "tools/cli").ancestor).to eq("far")
  end

  it "builds what no ancestor has, and everything that depends on it, by the shortest chain" do
    result = plan("near" => everything.except("base/cmake"), "far" => {})
    expect(kinds(result)).to eq("base/cmake" => :build, "base/logging" => :build, "base/types" => :build, "tools/cli" => :build)
    expect(result.decision(target, "base/cmake").cause.chain).to eq(["missing in all ancestors"])
    # base/types depends on base/cmake directly: one step, not through base/logging
    expect(result.decision(target, "base/types").cause.chain).to eq(["depends on base/cmake", "missing in all ancestors"])
    expect(result.decision(target, "tools/cli").cause.chain)
      .to eq(["depends on base/types", "depends on base/cmake", "missing in all ancestors"])
    expect(result.decision(target, "tools/cli").deb_name).to eq("rock-r-tools-cli")
    expect(result.decision(target, "tools/cli").version).to be_nil # Settlement gives versions
  end

  it "rebuilds a blacklisted package and its dependents only" do
    result = plan({ "near" => everything }, "blacklist" => [{ "match" => "base/logging", "reason" => "fix" }])
    expect(kinds(result)).to eq("base/cmake" => :inherit, "base/logging" => :build, "base/types" => :build, "tools/cli" => :build)
    expect(result.decision(target, "base/logging").cause.to_s).to eq('blacklisted by "base/logging" (fix)')
  end

  it "builds everything when no ancestor has the target" do
    result = plan({}, {})
    expect(kinds(result).values.uniq).to eq([:build])
    expect(result.decision(target, "base/cmake").cause.to_s).to eq("no ancestor has target bookworm/amd64")
  end

  it "refuses a blacklist entry that matches no package" do
    expect { plan({ "near" => everything }, "blacklist" => [{ "match" => "base/nothing" }]) }
      .to raise_error(Relspec::InvalidInput) { |error| expect(error.diagnostics.first.message).to include('"base/nothing" matches no package') }
  end

  it "notes the checkouts with uncommitted changes, naming five files at most, and whether the package set patches them" do
    change = Relspec::Catalog::UncommittedChanges::Change
    expect(plan({}).notes.grep(/uncommitted/)).to eq([])
    @uncommitted = { "base/types" => change.new(paths: %w[a b c d e f g], patched: false),
                     "base/cmake" => change.new(paths: ["x"], patched: true) }
    notes = plan({}).notes
    expect(notes).to include(
      "base/types has uncommitted changes in its checkout (a, b, c, d, e and 2 more): the release is made of its " \
      "commit, without them",
      "base/cmake has uncommitted changes in its checkout (x): the release is made of its commit, without them " \
      "(they are not exactly the package set's patches, which the release applies)"
    )
  end

  # bookworm: libruby3.1 provides ruby-minitest (= 5.15.0), the archive also has ruby-minitest 5.17.0
  it "takes a gem from the distribution at the newest version that fits, a Provides older than the newest package" do
    gem = Relspec::Catalog::Package.new(
      name: "minitest", package_set: "gems", build_type: "gem", commit_time: "2020-06-01T00:00:00Z", source_dir: nil,
      version: "5.15.0", vcs: Relspec::Catalog::Vcs.new(type: "gem", url: "https://rubygems.org", commit: nil)
    )
    catalog = Relspec::Catalog.new(packages: { "minitest" => gem }, layout: [], codenames: ["bookworm"])
    requirements = ->(text) { { "minitest" => [Gem::Requirement.new(text)] } }
    distribution = Relspec::Plan::DistributionPackages.new({ target => { "ruby-minitest" => %w[5.17.0 5.15.0] } }, [])
    decide = lambda do |requirement|
      resolution = Relspec::Catalog::GemResolution::Result.new(automatic: {}, requirements: requirements.call(requirement),
                                                               provided: [], notes: [])
      release = Relspec::Catalog::ReleaseCatalog.new(catalog, { "bookworm" => ["minitest"] }, { "bookworm" => {} },
                                                     "/workspace", {}, resolution)
      spec_file = Relspec::ReleaseSpec::SpecFile.new("specs/r.yml", Relspec::Yaml::LocatedDocument.parse("release: r\n", file: "specs/r.yml"))
      effective = Relspec::ReleaseSpec::EffectiveSpec.new({ "release" => "r", "targets" => { "bookworm" => ["amd64"] } }, {})
      planned = described_class.new(release_catalog: release, effective: effective, spec_file: spec_file, ancestors: [],
                                    inventory: Relspec::Plan::Inventory.new({}, {}), distribution: distribution).plan
      [planned.targets.fetch(target).fetch("minitest"), planned.notes]
    end
    decision, = decide.call("< 5.16")
    expect([decision.kind, decision.deb_name, decision.version]).to eq([:system, "ruby-minitest", "5.15.0"])
    decision, = decide.call(">= 5.16")
    expect(decision.version).to eq("5.17.0")
    decision, notes = decide.call("~> 5.16.0")
    expect(decision.kind).to eq(:build)
    expect(notes).to include("bookworm has ruby-minitest 5.17.0, 5.15.0, the release packages gem minitest 5.15.0")
  end
end
