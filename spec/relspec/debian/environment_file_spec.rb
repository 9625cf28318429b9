# frozen_string_literal: true

require "spec_helper"
require "autoproj"
require_relative "../../support/build_release"

# The env.yml every package installs in its prefix, as the rock-osdeps
# package set (the one Rock users have) consumes it: it loads
# /opt/rock/*/<deb>/env.yml of every active package with YAML.load_file and,
# per variable, reads the symbol keys :type (add_path, add, set,
# add_prefix), :values and :priority and calls the workspace environment's
# method of that name. A file in another shape crashed every autoproj
# command of a workspace that had one relspec package installed.
RSpec.describe "the env.yml relspec installs in each package", :tmpdir do
  before do
    @release = BuildRelease.new(@dir, "demo")
    @release.package("base/a", cmake: "")
    @release.compile
  end

  def debian_file(name)
    tarball = Dir.glob(File.join(@release.target_dir, "**", "#{@release.source('base/a')}_*.debian.tar.xz")).first
    text, status = Open3.capture2("tar", "-xJOf", tarball, "debian/#{name}")
    raise "no debian/#{name} in #{tarball}" unless status.success?

    text
  end

  it "is in the package set's format and gives autoproj the package's prefix" do
    path = File.join(@dir, "env.yml")
    File.write(path, debian_file("env.yml"))
    data = YAML.load_file(path) # as the package set loads it (Psych 4 allows symbols there)
    prefix = "/opt/rock/demo/#{@release.source('base/a')}"

    expect(data.keys).to all(be_a(String))
    data.each_value do |entry|
      expect(entry.keys).to contain_exactly(:type, :values, :priority)
      expect(%i[add_path add set add_prefix]).to include(entry[:type])
      expect(entry[:values]).to all(be_a(String))
      expect(entry[:priority]).to be_a(Integer)
    end
    env = Autobuild::Environment.new
    data.each { |name, entry| entry[:values].each { |value| env.public_send(entry[:type], name, value) } }
    expect(env.value("CMAKE_PREFIX_PATH")).to eq([prefix])
    expect(env.value("PATH")).to eq(["#{prefix}/bin"])
    expect(env.value("PKG_CONFIG_PATH")).to eq(["#{prefix}/lib/pkgconfig", "#{prefix}/share/pkgconfig"])
  end

  it "leaves relspec's own record of the package to relspec.yml" do
    expect(YAML.safe_load(debian_file("relspec.yml"))).to eq(
      "package" => "base/a", "release" => "demo", "prefix" => "/opt/rock/demo/#{@release.source('base/a')}",
      "dependencies" => []
    )
    expect(debian_file("rules")).to include("install -D -m 0644 debian/env.yml $(PACKAGE_ROOT)/env.yml")
  end
end
