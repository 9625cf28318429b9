# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/provenance"

# debian/changelog and debian/copyright: where the code comes from, under
# which license, dated by its commit.
RSpec.describe Relspec::Debian::Provenance do
  it "dates the changelog by the commit and names the repository, ref and commit" do
    input = build_input(package: { vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/pkg.git",
                                                                     "commit" => "a" * 40, "branch" => "master") })
    expect(described_class.new(input).changelog("0.1-1~bookworm")).to eq(<<~TEXT)
      rock-r-pkg (0.1-1~bookworm) bookworm; urgency=medium

        * Release r: pkg
          from https://example.org/pkg.git
          branch master, commit #{'a' * 40}

       -- M <m@example.org>  Thu, 04 Mar 2021 05:06:07 +0000
    TEXT
  end

  it "names a workspace repository relative to the workspace, and gives it no Source:" do
    vcs = Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "$AUTOPROJ_ROOT/src/pkg", "commit" => "a" * 40)
    provenance = described_class.new(build_input(package: { vcs: vcs, license: "GPL-2.0+", copyright: ["A B"] }))
    expect(provenance.changelog("1")).to include("from the autoproj workspace's src/pkg\n")
    copyright = provenance.copyright
    expect(copyright).not_to include("Source:")
    expect(copyright).to include("Copyright: A B\n", "pkg declares its license as: GPL-2.0+\n")
  end

  it "says the license is unknown and the holders are the authors when the package does not say" do
    copyright = described_class.new(build_input).copyright
    expect(copyright).to include("Source: https://example.org/pkg.git\n", "Copyright: the authors of pkg\n",
                                 "declares its license as: unknown\n")
  end
end
