# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/cache"
require "relspec/catalog/autoproj_source"

# The catalog cache must give back exactly what a fresh load gives, and
# notice every change autoproj would see.
RSpec.describe Relspec::Catalog::Cache do
  around do |example|
    Dir.mktmpdir("relspec-catalog-cache") do |dir|
      @builder = DemoWorkspace.build(File.join(dir, "ws"))
      @cache = described_class.new(File.join(dir, "cache"))
      example.run
    end
  end

  def fetch
    loads = 0
    catalog = @cache.fetch(@builder.root, distributions) do
      loads += 1
      load_catalog(@builder.root)
    end
    [catalog, loads]
  end

  it "loads once, then gives the same catalog from the cache" do
    first, loads = fetch
    expect(loads).to eq(1)
    second, loads = fetch
    expect(loads).to eq(0)
    expect(second).to eq(first)
  end

  it "loads again when a checkout moves to another commit" do
    fetch
    checkout = @builder.source_dir("base/logging")
    File.write(File.join(checkout, "NEW"), "x\n")
    @builder.git(checkout, "add", "NEW")
    @builder.git(checkout, "commit", "-q", "-m", "new", date: "2021-01-01T00:00:00Z")
    catalog, loads = fetch
    expect(loads).to eq(1)
    expect(catalog.package("base/logging").commit_time).to eq("2021-01-01T00:00:00Z")
  end

  it "loads again when a manifest.xml or an osdeps file changes" do
    fetch
    manifest = File.join(@builder.source_dir("data/models"), "manifest.xml")
    File.write(manifest, File.read(manifest).sub("<version>3</version>", "<version>4</version>"))
    catalog, loads = fetch
    expect([loads, catalog.package("data/models").version]).to eq([1, "4"])

    osdeps = File.join(@builder.root, "package_sets", "demo.pkgs", "demo.pkgs.osdeps")
    File.write(osdeps, File.read(osdeps).sub("buster: libboost1.67-all-dev", "buster: libboost1.70-all-dev"))
    catalog, loads = fetch
    expect(loads).to eq(1)
    expect(catalog.package("base/types").os_dependencies_for("buster").apt).to include("libboost1.70-all-dev")
  end
end
