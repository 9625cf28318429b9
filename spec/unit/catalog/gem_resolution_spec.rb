# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog"
require "relspec/catalog/package"
require "relspec/catalog/gem_resolution"
require "relspec/catalog/release_gems"

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
end
