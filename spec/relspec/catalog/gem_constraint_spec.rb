# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/release_catalog"
require_relative "../../support/rock_workspace_context"

# Rock's osdeps ask for `rice<4.0.0` (base/types' bindings use the Rice 3
# API): a `gems:` version outside an osdeps constraint is refused, as
# autoproj would never install it for that package. The rice gems here are
# stand-ins (GemBuilder): only their versions matter.
RSpec.describe "gem versions against the osdeps' constraints" do
  include_context "a real Rock workspace"

  before(:all) do
    @gems = File.join(@dir, "gems")
    %w[3.0.0 4.0.2].each { |version| GemBuilder.build(@gems, "rice", version) }
  end

  def load(version)
    body = "release: rel\nworkspace: #{@workspace.root}\ntargets: { bookworm: [amd64] }\n" \
           "gems: { rice: \"#{version}\" }\ngem_source: #{@gems}\n"
    with_specs("rel" => body) do |dir|
      return Relspec::Catalog::ReleaseCatalog.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml")))
    end
  end

  it "refuses a version the constraint excludes, naming the package, the constraint and the gems: entry" do
    expect { load("4.0.2") }.to raise_error(Relspec::InvalidInput) do |error|
      expect(error.diagnostics.map(&:rule)).to eq(["gem-constraint"])
      expect(error.diagnostics.first.message).to eq("base/types's osdeps ask for gem rice < 4.0.0, the release packages rice 4.0.2")
      expect(error.diagnostics.first.location.line).to eq(4)
    end
  end

  it "takes a version inside it" do
    expect(load("3.0.0").catalog.package("rice").version).to eq("3.0.0")
  end
end
