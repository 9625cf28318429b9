# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/debian_dir"
require "relspec/catalog/package"
require "relspec/release_specs/distribution"

# debian/ for old distributions: the compat level of each distribution's
# debhelper (docs/compile.md), declared the way that debhelper reads it, and
# rules that use no dh feature it lacks.
RSpec.describe "debian/ per debhelper compat level" do
  def render(build_type, compat, install_dir: "/opt/rock/r/rock-r-pkg")
    package = Relspec::Catalog::Package.new(
      name: "pkg", package_set: "set", build_type: build_type, commit_time: "2021-03-04T05:06:07Z", source_dir: "src/pkg",
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/pkg.git", "commit" => "a" * 40)
    )
    input = Relspec::Debian::BuildInput.new(
      package: package, deb_name: "rock-r-pkg", upstream: "0.1", codename: "x", release: "r",
      maintainer: "M <m@example.org>", install_dir: install_dir, dependencies: [], apt: [],
      gems: [], gem: nil, debhelper_compat: compat
    )
    Relspec::Debian::DebianDir.render(input, version: "0.1-1~x").transform_values(&:first)
  end

  def build_depends(files)
    files["control"][/^Build-Depends:(.*?)^(?=\S)/m, 1].split(",").map(&:strip).reject(&:empty?)
  end

  it "takes each distribution's level from the table" do
    levels = Relspec::ReleaseSpec::Distributions::BUILTIN.transform_values(&:debhelper_compat)
    expect(levels.values_at("xenial", "stretch", "bionic", "buster", "focal", "bullseye", "jammy", "bookworm", "noble", "trixie"))
      .to eq([9, 10, 11, 12, 12, 13, 13, 13, 13, 13])
    own = Relspec::ReleaseSpec::Distributions.with_overrides("focal" => { "debhelper_compat" => 11 })
    expect(own.fetch("focal").debhelper_compat).to eq(11)
  end

  %w[cmake autotools ruby import meta].each do |build_type|
    [9, 10, 11, 12, 13].each do |compat|
      it "declares compat #{compat} as that debhelper reads it, with only targets it has (#{build_type})" do
        files = render(build_type, compat)
        if compat < 11
          expect(build_depends(files)).to include("debhelper (>= #{compat})")
          expect(files["compat"]).to eq("#{compat}\n")
        else
          expect(build_depends(files)).to include("debhelper-compat (= #{compat})")
          expect(files).not_to have_key("compat")
        end
        # execute_before/after_* targets came with debhelper 12.8
        expect(files["rules"]).not_to match(/^execute_(before|after)_/)
        expect(files["rules"].scan(/^([\w-]+):/).flatten - ["%"]).to all(start_with("override_dh_"))
      end
    end
  end

  it "adds the autoreconf add-on where debhelper does not run it by itself (compat 9)" do
    old = render("autotools", 9)
    expect(old["rules"]).to include("dh $@ --buildsystem=autoconf --with autoreconf")
    expect(build_depends(old)).to include("dh-autoreconf")
    expect(render("autotools", 10)["rules"]).not_to include("--with autoreconf")
  end

  it "overrides dir-or-file-in-opt for /opt/rock, the release folder and the prefix" do
    overrides = render("cmake", 13)["rock-r-pkg.lintian-overrides"].lines.reject { |line| line.start_with?("#") }
    expect(overrides).to eq(["rock-r-pkg: dir-or-file-in-opt [opt/rock/]\n", "rock-r-pkg: dir-or-file-in-opt [opt/rock/r/]\n",
                             "rock-r-pkg: dir-or-file-in-opt [opt/rock/r/rock-r-pkg/*]\n",
                             "rock-r-pkg: custom-library-search-path\n"])
    shared = render("ruby", 13, install_dir: "/opt/rock/r")["rock-r-pkg.lintian-overrides"].lines.grep_v(/\A#/)
    expect(shared).to eq(["rock-r-pkg: dir-or-file-in-opt [opt/rock/]\n", "rock-r-pkg: dir-or-file-in-opt [opt/rock/r/*]\n"])
  end
end
