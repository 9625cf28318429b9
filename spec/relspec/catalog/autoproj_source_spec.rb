# frozen_string_literal: true

require "spec_helper"

# Loads the demo workspace with the real autoproj gem and compares what
# relspec read with what the builder created.
RSpec.describe "Relspec::Catalog::AutoprojSource" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-workspace")
    @builder = DemoWorkspace.build(@base)
    @before = tree_state(@builder.root)
    @catalog = load_catalog(@builder.root)
  end

  after(:all) { FileUtils.rm_rf(@base) }

  let(:catalog) { @catalog }

  it "reads build types and package sets" do
    types = catalog.packages.transform_values(&:build_type)
    expect(types).to eq("base/cmake" => "cmake", "base/logging" => "cmake", "base/types" => "cmake",
                        "data/models" => "import", "drivers/iodrivers_base" => "cmake",
                        "drivers/old_driver" => "cmake", "tools/legacy" => "autotools",
                        "tools/orocos.rb" => "ruby", "tools/unused" => "import")
    expect(catalog.packages.values.map(&:package_set).uniq).to eq(["demo.pkgs"])
  end

  it "reads dependencies and optional dependencies from manifest.xml" do
    DemoWorkspace::PACKAGES.each do |name, (_type, _date, _version, dependencies, optional, _osdeps)|
      # autoproj drops dependencies on ignored packages (tools/unused)
      expect(catalog.package(name).dependencies).to eq((dependencies - ["tools/unused"]).sort), name
      expect(catalog.package(name).optional_dependencies).to eq(optional.sort), name
    end
  end

  it "takes commits from the checkouts and commit times in UTC" do
    DemoWorkspace::PACKAGES.each do |name, (_type, date, version, *)|
      package = catalog.package(name)
      expect(package.vcs.commit).to eq(@builder.commit_of(name)), name
      expect(package.commit_time).to eq(date), name
      expect(package.version).to eq(version), name
    end
  end

  it "reads the VCS definition, relative to the workspace root" do
    expect(catalog.package("base/types").vcs.to_h).to eq(
      "type" => "git", "url" => "$AUTOPROJ_ROOT/repositories/base/types.git", "branch" => "master",
      "commit" => @builder.commit_of("base/types")
    )
  end

  it "reads manifest metadata" do
    package = catalog.package("base/logging")
    expect([package.license, package.maintainer, package.summary, package.source_dir])
      .to eq(["BSD-3-Clause", "Rock Packaging <rock-dev@example.org>", "base/logging", "src/base/logging"])
  end

  it "resolves OS dependencies per distribution, differing exactly where the .osdeps differ" do
    differing = catalog.packages.values.reject do |package|
      package.os_dependencies_for("bionic") == package.os_dependencies_for("buster")
    end
    expect(differing.map(&:name)).to eq(%w[base/types drivers/iodrivers_base tools/legacy tools/orocos.rb])
    types = catalog.package("base/types")
    expect(types.os_dependencies_for("bionic").to_h).to eq(
      "apt" => %w[build-essential cmake libboost-system-dev libboost-thread-dev libeigen3-dev]
    )
    expect(types.os_dependencies_for("buster").to_h).to eq(
      "apt" => %w[build-essential cmake libboost1.67-all-dev libeigen3-dev]
    )
    expect(catalog.package("tools/legacy").os_dependencies_for("buster").to_h["nonexistent"]).to eq(["motif"])
    expect(catalog.package("tools/legacy").os_dependencies_for("bionic").to_h["apt"]).to include("libmotif-dev")
    orocos = catalog.package("tools/orocos.rb")
    expect(orocos.os_dependencies_for("bionic").to_h).to eq("gems" => ["nokogiri"], "ignored" => %w[qt5-tools ruby])
    expect(orocos.os_dependencies_for("buster").to_h)
      .to eq("apt" => ["qttools5-dev-tools"], "gems" => ["nokogiri"], "ignored" => ["ruby"])
  end

  it "reads metapackages, layout, excluded and ignored packages" do
    expect(catalog.metapackages["demo.core"]).to eq(%w[base/logging base/types drivers/iodrivers_base tools/orocos.rb])
    expect(catalog.layout).to eq(%w[demo.core data/models tools/legacy])
    expect(catalog.excluded).to eq(["drivers/old_driver"])
    expect(catalog.ignored).to eq(["tools/unused"])
    expect(catalog.package("tools/unused").checked_out).to be(false)
  end

  it "leaves the workspace exactly as it was" do
    expect(tree_state(@builder.root)).to eq(@before)
  end

  it "gives the same catalog when loaded again" do
    expect(load_catalog(@builder.root)).to eq(catalog)
  end
end
