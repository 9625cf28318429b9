# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/release_catalog"
require_relative "../../support/rock_workspace_context"

# autoproj resolves the `ruby` osdep to `ruby<major><minor>` and loads
# `.osdeps-ruby<major><minor>` files for the Ruby it runs on; a release is
# built for the target distribution's Ruby (bionic 2.5, bookworm 3.1), not
# relspec's. utilrb's manifest.xml names the `ruby` osdep.
RSpec.describe "Ruby-version-specific osdeps" do
  include_context "a real Rock workspace"

  before(:all) do
    sets = File.join(@workspace.root, "package_sets", "orocos.toolchain")
    File.write(File.join(sets, "orocos.toolchain.osdeps-ruby25"), "ruby25:\n  debian,ubuntu: ruby2.5-dev\n")
    File.write(File.join(sets, "orocos.toolchain.osdeps-ruby31"), "ruby31:\n  debian,ubuntu: ruby3.1-dev\n")
  end

  it "are chosen per target distribution's Ruby" do
    with_specs("rel" => "release: rel\nworkspace: #{@workspace.root}\ntargets: { bionic: [amd64], bookworm: [amd64] }\n") do |dir|
      catalog = Relspec::Catalog::ReleaseCatalog.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml"))).catalog
      utilrb = catalog.package("utilrb")
      expect(utilrb.os_dependencies_for("bionic").apt).to include("ruby2.5-dev")
      expect(utilrb.os_dependencies_for("bionic").apt).not_to include("ruby3.1-dev")
      expect(utilrb.os_dependencies_for("bookworm").apt).to include("ruby3.1-dev")
      expect(utilrb.os_dependencies_for("bookworm").apt).not_to include("ruby2.5-dev")
    end
  end
end
