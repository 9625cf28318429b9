# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan"
require "relspec/debian/debian_dir"

# The input of each build's debian/ as DebianInputs makes it from a catalog
# and the target's decisions, in memory: here what a package's users need at
# their build time that its Depends leaves out (issue 32: base/cmake's
# macros call pkg-config, which reached no user's Build-Depends).
RSpec.describe Relspec::Plan::DebianInputs do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  # name => [build type, dependencies, apt names]
  let(:graph) do
    { "base/cmake" => ["cmake", [], %w[pkg-config ruby-dev libfoo-dev]],
      "base/logging" => ["cmake", ["base/cmake"], []],
      "tools/gen" => ["orogen", [], []],
      "base/types" => ["ruby", %w[base/logging tools/gen], ["ruby-rice"]],
      "gem/x" => ["gem", [], ["autoconf"]] }
  end
  # the package sets' environment settings, by package (rock.core's for tools/orogen_metadata)
  let(:environment) do
    { "base/cmake" => [{ "type" => "add_path", "name" => "OROGEN_PLUGIN_PATH", "values" => ["$PREFIX/share/orogen/plugins"] },
                       { "type" => "add_path", "name" => "PATH", "values" => ["$PREFIX/sbin"] },
                       { "type" => "set", "name" => "BAD NAME", "values" => ["x"] }],
      "tools/gen" => [{ "type" => "set", "name" => "GEN_MODE", "values" => ["fast"] }] }
  end
  # CMake defines naming other packages' prefixes (Catalog::PrefixMarkers), by package
  let(:defines) do
    { "base/logging" => { "CM" => "${prefix:base/cmake}/lib", "GONE" => "${prefix:not/released}", "TYPE" => "Release",
                          "RUBY_EXECUTABLE" => "${ruby}" } }
  end
  # rake tasks that compile an extension (Catalog::RubyExtension), by package
  let(:extension_tasks) { {} }
  let(:catalog) do
    packages = graph.to_h do |name, (type, dependencies, apt)|
      [name, Relspec::Catalog::Package.new(
        name: name, package_set: "set", build_type: type, commit_time: "2020-06-01T00:00:00Z", source_dir: "src/#{name}",
        version: "1.0", dependencies: dependencies, defines: defines.fetch(name, {}),
        environment: environment.fetch(name, []), extension_task: extension_tasks[name],
        os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(apt: apt) },
        vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/#{name}.git", commit: "c" * 40)
      )]
    end
    Relspec::Catalog.new(packages: packages, layout: graph.keys, codenames: ["bookworm"])
  end
  let(:inputs) do
    effective = Relspec::ReleaseSpec::EffectiveSpec.new(
      { "release" => "r", "targets" => { "bookworm" => ["amd64"] }, "install_prefix" => "/opt/rock",
        "maintainer" => "M <m@example.org>" }, {}
    )
    release_catalog = Relspec::Catalog::ReleaseCatalog.new(catalog, { "bookworm" => graph.keys }, { "bookworm" => {} },
                                                           "/workspace", {})
    described_class.new(effective: effective, ancestors: [], release_catalog: release_catalog)
  end

  def decisions(kinds = {})
    graph.keys.to_h do |name|
      [name, Relspec::Plan::Decision.new(package: name, kind: kinds.fetch(name, :build), deb_name: "rock-r-#{name.tr('/', '-')}",
                                         version: Relspec::Debian::PackageVersion.new("1.0", 1, "bookworm")).freeze]
    end
  end

  def input(name, all = decisions)
    inputs.for(target, all[name], "1.0", all)
  end

  def control(input)
    Relspec::Debian::DebianDir.render(input, version: "1.0-1~bookworm").transform_values(&:first).fetch("control")
  end

  def field(text, name)
    text[/^#{name}:(.*?)^(?=\S)/m, 1].split(",").map(&:strip)
  end

  # autoproj builds with every dependency's environment: tools/logger's oroGen
  # run found no metadata_support plugin without OROGEN_PLUGIN_PATH
  it "carries the package sets' variables of the whole closure into debian/rules, and only plain names" do
    expect(input("base/types").closure_environment).to eq(%w[GEN_MODE OROGEN_PLUGIN_PATH])
    expect(input("base/logging").closure_environment).to eq(%w[OROGEN_PLUGIN_PATH])
    expect(input("base/cmake").closure_environment).to eq([])
    rules = Relspec::Debian::DebianDir.render(input("base/logging"), version: "1.0-1~bookworm").fetch("rules").first
    expect(rules).to include(' "OROGEN_PLUGIN_PATH=$${OROGEN_PLUGIN_PATH:-}")',
                             "export OROGEN_PLUGIN_PATH := $(call relspec_get,OROGEN_PLUGIN_PATH)\n")
    expect(rules).to match(/^relspec_env := \$\(shell unset .* GEM_PATH OROGEN_PLUGIN_PATH; /)
    expect(rules).not_to include("BAD NAME")
  end

  it "gives a package the build-only tools of its whole dependency closure, not those of others" do
    expect(input("base/types").closure_tools).to eq(%w[cmake pkg-config ruby-dev])
    expect(input("base/logging").closure_tools).to eq(%w[cmake pkg-config ruby-dev])
    expect(input("base/cmake").closure_tools).to eq([])
    expect(input("gem/x").closure_tools).to eq([])
  end

  it "writes them into Build-Depends and leaves Depends as the package needs to run" do
    types = control(input("base/types"))
    expect(field(types, "Build-Depends")).to include("pkg-config", "ruby-dev", "cmake", "ruby-rice")
    expect(field(types, "Depends")).not_to include("pkg-config", "ruby-dev", "cmake")
    cmake = control(input("base/cmake"))
    expect(field(cmake, "Depends")).to include("libfoo-dev")
    expect(field(cmake, "Depends")).not_to include("pkg-config")
  end

  it "takes nothing from a dependency the distribution provides (a system decision)" do
    expect(input("base/types", decisions("base/logging" => :system)).closure_tools).to eq(%w[cmake pkg-config])
  end

  it "gives a define naming a package's prefix the release prefix of that package, leaving out unreleased ones, " \
     "and one naming the workspace's Ruby the target's" do
    logging = input("base/logging")
    expect(logging.defines).to eq("CM" => "/opt/rock/r/rock-r-base-cmake/lib", "RUBY_EXECUTABLE" => "/usr/bin/ruby3.1",
                                  "TYPE" => "Release")
    rules = Relspec::Debian::DebianDir.render(logging, version: "1.0-1~bookworm").fetch("rules").first
    expect(rules).to include("-DCM=/opt/rock/r/rock-r-base-cmake/lib -DRUBY_EXECUTABLE=/usr/bin/ruby3.1 -DTYPE=Release " \
                             "-DCMAKE_INSTALL_PREFIX")
    expect(rules).not_to include("GONE")
    expect(input("base/logging", decisions("base/cmake" => :system)).defines)
      .to eq("CM" => "/usr/lib", "RUBY_EXECUTABLE" => "/usr/bin/ruby3.1", "TYPE" => "Release")
  end

  # debian/ renders from BuildInput alone: the plan checks the task that
  # reaches debian/rules' rake command (a catalog can be written by hand)
  describe "the extension task" do
    let(:extension_tasks) { { "base/types" => "default", "gem/x" => "x;y" } }

    it "is the package's, checked; nil without one" do
      expect(input("base/types").extension_task).to eq("default")
      expect(input("base/cmake").extension_task).to be_nil
    end

    it "refuses one a shell would read, from a catalog written by hand" do
      expect { input("gem/x") }.to raise_error(ArgumentError, /bad rake task "x;y"/)
    end
  end
end
