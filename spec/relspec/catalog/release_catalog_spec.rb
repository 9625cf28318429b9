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
    expect(selections["buster"].unavailable.transform_values { |reason| reason.to_h.compact }).to eq(
      "gui/app" => { dependency: "gui/toolkit" }, "gui/toolkit" => { osdeps: ["motif"] },
      "gui/viewer" => { dependency: "gui/app" }
    )
  ensure
    FileUtils.rm_rf(base)
  end

  context "with exclusions and osdeps of other systems, as autoproj spreads them" do
    before(:all) do
      @gaps = Dir.mktmpdir("relspec-exclusions")
      builder = WorkspaceBuilder.new(@gaps)
      date = "2020-01-01T00:00:00Z"
      builder.package("slam/maps", type: :cmake, date: date)
      builder.package("slam/core", type: :cmake, date: date, dependencies: ["slam/maps"])
      builder.package("slam/app", type: :cmake, date: date, dependencies: ["slam/core"])
      builder.package("slam/viewer", type: :cmake, date: date)
      builder.package("gui/legacy", type: :cmake, date: date, osdeps: ["oldqt"])
      builder.package("gui/shell", type: :cmake, date: date, dependencies: ["gui/legacy"])
      builder.metapackage("slam.weak", "slam/app", "slam/viewer")
      builder.metapackage("slam.strong", "slam/app", "slam/viewer")
      builder.layout("slam/viewer")
      # a package set excluding a package itself, and a weak metapackage (as rock's `rock`)
      builder.autobuild("Autoproj.manifest.exclude_package 'slam/maps', 'needs a newer PCL'\n" \
                        "metapackage('slam.weak').weak_dependencies = true\n")
      # defined for Ubuntu only: autoproj's WRONG_OS on buster
      # and a key with a space, which autoproj matches with no system
      builder.osdeps("oldqt:\n  ubuntu: libqt4-dev\nlibfoo:\n  \"ubuntu, debian\": libfoo-dev\n")
      builder.create
      @gaps_root = builder.root
    end

    after(:all) { FileUtils.rm_rf(@gaps) if @gaps }

    it "leaves out a weak metapackage's packages that need an excluded one, with the chain" do
      selection = release("select: [slam.weak]", workspace: @gaps_root).selections.fetch("buster")
      expect(selection.names).to eq(%w[slam.weak slam/viewer])
      expect(selection.unavailable.transform_values { |reason| reason.to_h.compact }).to eq(
        "slam/app" => { dependency: "slam/core" }, "slam/core" => { dependency: "slam/maps" },
        "slam/maps" => { excluded: "needs a newer PCL" }
      )
    end

    it "shows the chain in plan and why" do
      with_specs("rel" => "release: rel\nworkspace: #{@gaps_root}\ntargets: { buster: [amd64] }\nselect: [slam.weak]\n") do |dir|
        plan = relspec("plan", File.join(dir, "rel.yml"))
        expect(plan.exit_code).to eq(0), plan.stderr
        expect(plan.stdout).to match(%r{slam/maps +excluded by autoproj: needs a newer PCL})
        why = relspec("why", File.join(dir, "rel.yml"), "slam/app", "--target", "buster/amd64")
        expect(why.stdout).to eq("buster/amd64: slam/app cannot be built there, because:\n  depends on slam/core\n    " \
                                 "└ depends on slam/maps\n      └ excluded by autoproj: needs a newer PCL\n")
      end
    end

    it "refuses a strong metapackage, or a package, that needs an excluded package, naming the chain" do
      expect(errors_of("select: [slam.strong]", workspace: @gaps_root)).to include(
        "unavailable-selection: slam.strong is selected, but its package slam/app cannot be built on buster: it " \
        "requires slam/core, which requires slam/maps, which is excluded (needs a newer PCL) (autoproj refuses this " \
        "too, unless slam.strong has weak dependencies; select its other packages, or leave these out (`leave_out`))"
      )
      expect(errors_of("select: [slam/core]", workspace: @gaps_root).first).to start_with(
        "unavailable-selection: slam/core is selected, but cannot be built on bionic: it requires slam/maps, which is " \
        "excluded (needs a newer PCL)"
      )
    end

    it "makes a package unavailable where its osdep is defined for other systems only, and its users too" do
      catalog = nil
      expect { catalog = release("select: [slam/viewer]", workspace: @gaps_root).catalog }
        .to output(/osdeps key "ubuntu, debian" of libfoo in .*demo.pkgs.osdeps: autoproj splits keys at commas without removing spaces, so it matches no system; write "ubuntu,debian"/).to_stderr
      expect(catalog.package("gui/legacy").os_dependencies_for("buster").other_os).to eq(["oldqt"])
      expect(catalog.package("gui/legacy").os_dependencies_for("bionic").apt).to include("libqt4-dev")
      expect(errors_of("select: [gui/shell]", workspace: @gaps_root)).to eq([
        "unavailable-selection: gui/shell is selected, but cannot be built on buster: it requires gui/legacy, which " \
        "needs the osdep oldqt, which the osdeps files define for other systems only (select what needs it instead, " \
        "or leave it out (`leave_out`))"
      ])
      expect(release("select: [gui/shell]\nleave_out: [{ match: gui/legacy, reason: qt4, targets: [buster] }]",
                     workspace: @gaps_root).selections.fetch("buster").unavailable.keys).to eq(%w[gui/legacy gui/shell])
    end
  end

  it "requires a workspace" do
    with_specs("rel" => "release: rel\ntargets: { bionic: [amd64] }\n") do |dir|
      expect { described_class.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml"))) }
        .to raise_error(Relspec::InvalidInput, /names no workspace/)
    end
  end
end
