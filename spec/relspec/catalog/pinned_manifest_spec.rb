# frozen_string_literal: true

require "spec_helper"
require "open3"
require "relspec/catalog/release_catalog"
require_relative "../../support/rock_workspace_context"

# A pin builds another commit than the checkout's, and that commit declares
# its own dependencies: base/cmake's tag rock-15.05 names only cmake in its
# manifest.xml, master names cmake and pkg-config (real repositories from
# ../shared/fixtures/rock-repos, loaded by autoproj).
RSpec.describe "dependencies of a pinned package" do
  include_context "a real Rock workspace"

  def os_apt(body)
    with_specs("rel" => "release: rel\nworkspace: #{@workspace.root}\ntargets: { bookworm: [amd64] }\n#{body}") do |dir|
      catalog = Relspec::Catalog::ReleaseCatalog.load(Relspec::ReleaseSpec.resolve(File.join(dir, "rel.yml")))
      return catalog.catalog.package("base/cmake").os_dependencies_for("bookworm").apt
    end
  end

  it "come from the pinned commit's manifest.xml, read from git, not from the working tree" do
    checkout = @workspace.source_dir("base/cmake")
    before = File.read(File.join(checkout, "manifest.xml"))
    expect(os_apt("")).to include("cmake", "pkg-config")

    pinned = os_apt("pins: { base/cmake: { tag: rock-15.05 } }")
    expect(pinned).to include("cmake")
    expect(pinned).not_to include("pkg-config")
    # the checkout is left as it was
    expect(File.read(File.join(checkout, "manifest.xml"))).to eq(before)
    status, = Open3.capture2("git", "-C", checkout, "status", "--porcelain")
    expect(status).to eq("")
  end

  it "stay the checkout's for a pin on the commit the checkout has" do
    head, = Open3.capture2("git", "-C", @workspace.source_dir("base/cmake"), "rev-parse", "HEAD")
    expect(os_apt("pins: { base/cmake: { commit: #{head.strip} } }")).to include("cmake", "pkg-config")
  end
end
