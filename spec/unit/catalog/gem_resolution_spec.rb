# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog"
require "relspec/catalog/package"
require "relspec/catalog/gem_resolution"
require "relspec/catalog/release_gems"
require "relspec/catalog/gem_depends"

# Gem osdeps resolved against a distribution's archive, in memory. The gem
# source stands for GemVersions with its two calls (what it lists, and
# where); it lists nothing, so a gem the distribution cannot provide is an
# error here.
RSpec.describe Relspec::Catalog::GemResolution do
  let(:catalog) do
    package = Relspec::Catalog::Package.new(
      name: "app", package_set: "set", build_type: "ruby", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/app",
      os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: ["minitest<5.16"]) },
      vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/app.git", commit: "c" * 40)
    )
    Relspec::Catalog.new(packages: { "app" => package }, layout: ["app"], codenames: ["bookworm"])
  end
  let(:no_gems) do
    Struct.new(:where) do
      def of(_name) = []
      def folder? = false
    end.new("gem_source")
  end

  def resolve(archive)
    described_class.new(catalog: catalog, selected: { "bookworm" => ["app"] }, pinned: {},
                        archives: { "bookworm/amd64" => archive }, locked: {}, versions: no_gems,
                        fetch: ->(*) { raise "nothing is fetched" }, blacklisted: ->(_) { false }, location: nil).call
  end

  # bookworm: ruby-minitest 5.17.0-1, and libruby3.1's Provides: ruby-minitest (= 5.15.0)
  it "takes a gem from the distribution when any version the archive has fits, not only the newest" do
    expect(resolve("ruby-minitest" => %w[5.17.0-1 5.15.0]).automatic).to eq({})
    expect { resolve("ruby-minitest" => %w[5.17.0-1]) }
      .to raise_error(Relspec::InvalidInput) { |error| expect(error.diagnostics.first.message).to include("no version of gem minitest") }
  end

  # trixie: ruby-dry-types 1.2.2 depends on ruby-dry-core, which the release packages (Debian's 0.7.1 is too old)
  describe "a distribution gem that depends on a gem packaged here" do
    let(:archives) do
      { "dry-types" => { "1.2.2" => {}, "1.9.1" => { "dry-core" => "~> 1.0" } }, "dry-core" => { "1.2.0" => {} } }
    end
    let(:versions) do
      listed = archives.transform_values { |found| found.keys.reverse.map { |version| Gem::Version.new(version) } }
      Struct.new(:listed, :where) do
        def of(name) = listed.fetch(name, [])
        def folder? = false
      end.new(listed, "gem_source")
    end
    let(:fetch) do
      lambda do |name, version|
        Struct.new(:name, :version, :runtime_dependencies)
              .new(name, version, archives.fetch(name).fetch(version).map { |gem, text| [gem, Gem::Requirement.new(text)] })
      end
    end

    def app_needing(*gems)
      package = catalog.package("app").with(os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: gems) })
      Relspec::Catalog.new(packages: { "app" => package }, layout: ["app"], codenames: ["bookworm"])
    end

    def resolve_with(depends, archive)
      described_class.new(catalog: app_needing("dry-types>= 1.1", "dry-core>= 1.0"), selected: { "bookworm" => ["app"] },
                          pinned: {}, archives: -> { { "bookworm/amd64" => archive } }, locked: {}, versions: versions,
                          fetch: fetch, blacklisted: ->(_) { false }, location: nil,
                          depends: -> { { "bookworm/amd64" => depends } }).call
    end

    let(:archive) { { "ruby-dry-types" => %w[1.2.2-2], "ruby-dry-core" => %w[0.7.1-1] } }

    it "packages it too, at the highest version that fits, and says why" do
      types = Relspec::Catalog::GemDepends.new(name: "ruby-dry-types", version: "1.2.2-2", depends: ["ruby-dry-core"])
      result = resolve_with({ "ruby-dry-types" => types }, archive)
      expect(result.automatic).to eq("dry-core" => "1.2.0", "dry-types" => "1.9.1")
      expect(result.notes).to eq(["ruby-dry-types 1.2.2-2 (bookworm) depends on dry-core, which the release packages at " \
                                  "1.2.0: gem dry-types is packaged here"])
      # without Debian's Depends it is the distribution's, as before
      expect(resolve_with({}, archive).automatic).to eq("dry-core" => "1.2.0")
    end

    it "names the shadowing when no version of it can be had" do
      archives.delete("dry-types")
      types = Relspec::Catalog::GemDepends.new(name: "ruby-dry-types", version: "1.2.2-2", depends: ["ruby-dry-core"])
      expect { resolve_with({ "ruby-dry-types" => types }, archive) }.to raise_error(Relspec::InvalidInput) do |error|
        expect(error.diagnostics.map(&:message))
          .to eq(["no version of gem dry-types in gem_source fits what is asked: app's osdep dry-types>= 1.1 (>= 1.1); " \
                  "it has none (not taken from the distribution: ruby-dry-types 1.2.2-2 (bookworm) depends on dry-core, " \
                  "which the release packages at 1.2.0)"])
      end
    end
  end
end
