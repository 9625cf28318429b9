# frozen_string_literal: true

require_relative "../unit_helper"
require_relative "../../support/in_process_gem"
require "relspec/catalog"
require "relspec/catalog/package"
require "relspec/catalog/release_catalog"
require "relspec/catalog/snapshot_source"
require "relspec/catalog/gem_archive"
require "relspec/catalog/gem_depends"
require "relspec/release_specs"

# A release's catalog with its gems resolved, all in memory and in a
# temporary folder: a catalog snapshot as the workspace, .gem files built
# in-process (Gem::Package) in a gem_source folder, and the distribution's
# ruby-* packages as Plan::GemArchives hands them (#call, #depends).
RSpec.describe Relspec::Catalog::ReleaseCatalog do
  around do |example|
    Dir.mktmpdir("relspec-release-catalog") do |dir|
      @dir = dir
      example.run
    end
  end

  def write_gem(name, version, dependencies = {}, ruby: nil)
    InProcessGem.write(File.join(@dir, "gems"), name, version, dependencies: dependencies, ruby: ruby)
  end

  def spec_path
    package = Relspec::Catalog::Package.new(
      name: "tools/rest", package_set: "set", build_type: "ruby", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/rest",
      os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: ["types>= 1.1", "core>= 1.0"]) },
      vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/rest.git", commit: "c" * 40)
    )
    catalog = Relspec::Catalog.new(packages: { "tools/rest" => package }, layout: ["tools/rest"], codenames: ["bookworm"])
    Relspec::Catalog::SnapshotSource.write(File.join(@dir, "catalog.yml"), catalog)
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rel.yml"),
               "release: rel\nworkspace: ../catalog.yml\ntargets: { bookworm: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\ngem_source: ../gems\n")
    File.join(@dir, "specs", "rel.yml")
  end

  # trixie's case: ruby-types 1.2.2 depends on ruby-core, which is too old, so the release packages core
  def load(depends)
    write_gem("core", "1.2.0")
    write_gem("types", "1.9.1", { "core" => "~> 1.0" })
    archives = Struct.new(:depends) do
      def call = { "bookworm/amd64" => { "ruby-types" => %w[1.2.2-2], "ruby-core" => %w[0.7.1-1] } }
    end.new({ "bookworm/amd64" => depends })
    fetch = lambda do |name, version|
      path = File.join(@dir, "gems", "#{name}-#{version}.gem")
      Relspec::Catalog::GemArchive.new(name, version, path, path)
    end
    described_class.load(Relspec::ReleaseSpec.resolve(spec_path), gem_fetch: fetch, gem_archives: archives)
  end

  it "hands the archive's gem depends to gem resolution: a distribution gem the release's gems shadow is packaged" do
    types = Relspec::Catalog::GemDepends.new(name: "ruby-types", version: "1.2.2-2", depends: ["ruby-core"])
    loaded = load("ruby-types" => types)
    expect(loaded.catalog.package("types").version).to eq("1.9.1")
    expect(loaded.catalog.package("tools/rest").dependencies).to include("core", "types")
    expect(loaded.gem_resolution.notes)
      .to eq(["ruby-types 1.2.2-2 (bookworm) depends on core, which the release packages at 1.2.0: gem types is packaged here"])

    expect(load({}).catalog.package?("types")).to be(false)
  end

  # bookworm's Ruby is 3.1: core 1.3.0 would install there but not load
  it "hands the targets' Ruby to gem resolution: what needs a newer one is not packaged" do
    write_gem("core", "1.3.0", ruby: ">= 3.2")
    types = Relspec::Catalog::GemDepends.new(name: "ruby-types", version: "1.2.2-2", depends: ["ruby-core"])
    expect(load("ruby-types" => types).catalog.package("core").version).to eq("1.2.0")
  end
end
