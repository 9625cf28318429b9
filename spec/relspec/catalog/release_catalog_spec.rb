# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/release_catalog"
require "relspec/catalog/snapshot_source"

# A release's packages: selection, pins and the errors a maintainer meets.
RSpec.describe Relspec::Catalog::ReleaseCatalog do
  before(:all) do
    @base = Dir.mktmpdir("relspec-workspace")
    @builder = DemoWorkspace.build(@base)
    @snapshot = File.join(@base, "catalog.yml")
    File.write(@snapshot, Relspec::Catalog::SnapshotSource.dump(load_catalog(@builder.root)))
  end

  after(:all) { FileUtils.rm_rf(@base) }

  def release(body, workspace: @snapshot)
    with_specs("rel" => "release: rel\nworkspace: #{workspace}\ntargets: { bionic: [amd64], buster: [amd64] }\n#{body}") do |dir|
      return described_class.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml")))
    end
  end

  def errors_of(body, workspace: @snapshot)
    release(body, workspace: workspace)
    raise "expected InvalidInput"
  rescue Relspec::InvalidInput => e
    e.diagnostics.map { |d| "#{d.rule}: #{d.message}#{" (#{d.hint})" if d.hint}" }
  end

  it "selects the layout with dependencies by default, without excluded or ignored packages" do
    names = release("").selections.fetch("bionic").names
    expect(names).to eq(%w[base/cmake base/logging base/types data/models drivers/iodrivers_base tools/legacy
                           tools/orocos.rb])
  end

  it "expands metapackages and follows optional dependencies that are available" do
    expect(release("select: [base/types]").selections["buster"].names).to eq(%w[base/cmake base/logging base/types])
    expect(release("select: [demo.core]").selections["buster"].names)
      .to eq(%w[base/cmake base/logging base/types demo.core drivers/iodrivers_base tools/orocos.rb])
  end

  it "adds a metapackage selected by name as a package depending on its members" do
    release = release("select: [demo.core, data/models]")
    meta = release.catalog.package("demo.core")
    expect([meta.build_type, meta.dependencies, meta.commit_time])
      .to eq(["meta", %w[base/logging base/types drivers/iodrivers_base tools/orocos.rb], "2020-06-05T16:45:00Z"])
    expect(release.selections["bionic"].names).to include("demo.core", "data/models")
  end

  it "loads the same selection from the workspace and from its snapshot" do
    from_workspace = release("", workspace: @builder.root)
    from_snapshot = release("")
    expect(from_workspace.selections.transform_values(&:names)).to eq(from_snapshot.selections.transform_values(&:names))
    expect(from_workspace.catalog).to eq(from_snapshot.catalog)
  end

  it "names unknown packages in select with a suggestion" do
    expect(errors_of("select: [base/typess]")).to eq([
      'unknown-package: select names "base/typess", which is neither a package nor a metapackage of the workspace ' \
      '(did you mean "base/types"?)'
    ])
  end

  it "refuses a selected package the manifest excludes, and a dependency on one" do
    expect(errors_of("select: [drivers/old_driver]"))
      .to eq(["excluded-package: drivers/old_driver is selected but excluded by the workspace manifest"])
  end

  it "resolves a tag pin in the checkout, to the tagged commit and its time" do
    catalog = release("pins: { base/types: { tag: v2.0.0 } }", workspace: @builder.root).catalog
    tagged = @builder.git(@builder.source_dir("base/types"), "rev-parse", "v2.0.0^{commit}")
    package = catalog.package("base/types")
    expect([package.vcs.tag, package.vcs.commit, package.commit_time]).to eq(["v2.0.0", tagged, "2020-03-02T14:00:00Z"])
  end

  it "resolves an abbreviated commit pin to the full commit" do
    head = @builder.commit_of("base/cmake")
    package = release("pins: { base/cmake: { commit: #{head[0, 8]} } }", workspace: @builder.root).catalog.package("base/cmake")
    expect([package.vcs.commit, package.commit_time]).to eq([head, "2020-05-04T08:00:00Z"])
  end

  it "refuses a pin the checkout does not have, and a pin on an unknown package" do
    expect(errors_of("pins: { base/types: { tag: v9 }, base/typo: { tag: v1 } }", workspace: @builder.root)).to eq([
      "pin-not-found: pinned tag v9 of base/types is not in its checkout src/base/types (fetch it into the checkout " \
      "(autoproj update, or git fetch in src/base/types), or fix the pin)",
      'unknown-package: pin names "base/typo", which is not a package of the workspace (did you mean "base/types"?)'
    ])
  end

  it "leaves out on a codename what needs an OS dependency marked nonexistent there, and what requires it" do
    base = Dir.mktmpdir("relspec-gaps")
    builder = WorkspaceBuilder.new(base)
    builder.package("gui/widgets", type: :cmake, date: "2020-01-01T00:00:00Z")
    builder.package("gui/toolkit", type: :cmake, date: "2020-01-01T00:00:00Z", osdeps: ["motif"],
                                   dependencies: ["gui/widgets"])
    builder.package("gui/app", type: :cmake, date: "2020-01-02T00:00:00Z", dependencies: ["gui/toolkit"])
    builder.package("gui/viewer", type: :cmake, date: "2020-01-03T00:00:00Z", dependencies: ["gui/app"])
    builder.package("gui/plugins", type: :cmake, date: "2020-01-04T00:00:00Z", optional: ["gui/toolkit"])
    builder.layout("gui/viewer", "gui/plugins")
    builder.osdeps("motif:\n  debian:\n    buster: nonexistent\n    default: libmotif-dev\n  ubuntu: libmotif-dev\n")
    builder.create
    selections = release("", workspace: builder.root).selections
    expect(selections["bionic"].names).to eq(%w[gui/app gui/plugins gui/toolkit gui/viewer gui/widgets])
    expect(selections["bionic"].unavailable).to eq({})
    # gui/widgets is left out too: only gui/toolkit needed it
    expect(selections["buster"].names).to eq(%w[gui/plugins])
    expect(selections["buster"].unavailable.transform_values(&:to_h)).to eq(
      "gui/app" => { osdeps: nil, left_out: nil, dependency: "gui/toolkit" },
      "gui/toolkit" => { osdeps: ["motif"], left_out: nil, dependency: nil },
      "gui/viewer" => { osdeps: nil, left_out: nil, dependency: "gui/app" }
    )
  ensure
    FileUtils.rm_rf(base)
  end

  it "requires a workspace" do
    with_specs("rel" => "release: rel\ntargets: { bionic: [amd64] }\n") do |dir|
      expect { described_class.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml"))) }
        .to raise_error(Relspec::InvalidInput, /names no workspace/)
    end
  end
end
