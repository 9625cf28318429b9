# frozen_string_literal: true

require "spec_helper"
require "open3"
require "relspec/debian/debian_dir"
require "relspec/catalog/package"
require "relspec/release_specs/distribution"

# The build environment of debian/rules (docs/compile.md): rules names only
# the direct dependencies and takes the rest from their installed env.sh.
# Real GNU make evaluates the rendered rules against prefixes where the
# rendered env.sh files are installed, as a build-dependency leaves them.
RSpec.describe "debian/rules build environment" do
  around do |example|
    Dir.mktmpdir("relspec-build-env") do |dir|
      @root = dir
      example.run
    end
  end

  # Renders +name+ (depending on +dependencies+, already installed) and
  # installs its env.sh into its prefix; returns its debian/rules.
  def package(name, dependencies, ruby_dirs: [])
    catalog_package = Relspec::Catalog::Package.new(
      name: name, package_set: "set", build_type: "cmake", commit_time: "2021-03-04T05:06:07Z", source_dir: "src/#{name}",
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/x.git", "commit" => "a" * 40),
      dependencies: dependencies
    )
    dependency_inputs = dependencies.map do |dep|
      Relspec::Debian::BuildInput::Dependency.new(deb_name: deb(dep), version: "0.1-1", install_dir: prefix(dep))
    end
    input = Relspec::Debian::BuildInput.new(
      package: catalog_package, deb_name: deb(name), upstream: "0.1", codename: "bookworm", release: "r",
      maintainer: "M <m@example.org>", install_dir: prefix(name), apt: [], gems: [], dependencies: dependency_inputs,
      ruby_dirs: ruby_dirs
    )
    @files = Relspec::Debian::DebianDir.render(input, version: "0.1-1~bookworm").transform_values(&:first)
    FileUtils.mkdir_p(prefix(name))
    File.write(File.join(prefix(name), "env.sh"), @files.fetch("env.sh"))
    @files.fetch("rules")
  end

  def deb(name) = "rock-r-#{name.tr('/', '-')}"
  def prefix(name) = File.join(@root, "opt", deb(name))

  # What a recipe of +rules+ sees, with a builder's environment that sets
  # none of the search paths.
  def build_environment(rules)
    path = File.join(@root, "rules")
    File.write(path, "#{rules}\nrelspec-show:\n\t@env\n")
    out, err, status = Open3.capture3({ "CMAKE_PREFIX_PATH" => "/stale", "GEM_PATH" => nil, "RUBYLIB" => nil },
                                      "make", "-s", "-f", path, "relspec-show", chdir: @root)
    expect(status).to be_success, err
    out.lines.to_h { |line| line.chomp.split("=", 2) }
  end

  it "names only the direct dependencies and still finds the whole closure" do
    package("base/cmake", [])
    package("base/logging", ["base/cmake"])
    rules = package("base/types", ["base/logging"])
    expect(rules).to include("RELSPEC_DEPENDENCIES := #{prefix('base/logging')}\n")
    expect(rules).not_to include(prefix("base/cmake"))
    env = build_environment(rules)
    expect(env.fetch("CMAKE_PREFIX_PATH")).to eq("#{prefix('base/logging')}:#{prefix('base/cmake')}")
    expect(env.fetch("PKG_CONFIG_PATH").split(":"))
      .to eq(%w[base/logging base/cmake].flat_map { |name| ["#{prefix(name)}/lib/pkgconfig", "#{prefix(name)}/share/pkgconfig"] })
    expect(env.fetch("LD_LIBRARY_PATH")).to eq("#{prefix('base/logging')}/lib:#{prefix('base/cmake')}/lib")
    expect(env.fetch("PATH")).to start_with("#{prefix('base/logging')}/bin:#{prefix('base/cmake')}/bin:")
    expect(env.fetch("RUBYLIB")).to eq("#{prefix('base/logging')}/lib:#{prefix('base/cmake')}/lib")
    # GEM_PATH replaces RubyGems' default path: the default stays after the prefixes
    expect(env.fetch("GEM_PATH")).to start_with("#{prefix('base/logging')}/gems:#{prefix('base/cmake')}/gems:")
    expect(env.fetch("GEM_PATH").split(":").size).to be > 2
  end

  it "adds a dependency shared by two paths of the graph once" do
    package("base/cmake", [])
    package("base/logging", ["base/cmake"])
    package("base/numeric", ["base/cmake"])
    rules = package("base/types", ["base/logging", "base/numeric"])
    expect(build_environment(rules).fetch("CMAKE_PREFIX_PATH").split(":"))
      .to eq([prefix("base/numeric"), prefix("base/logging"), prefix("base/cmake")])
  end

  it "sets nothing for a package without dependencies of the release" do
    rules = package("base/cmake", [])
    expect(rules).not_to include("RELSPEC_DEPENDENCIES")
    expect(build_environment(rules).fetch("CMAKE_PREFIX_PATH")).to eq("/stale")
  end

  # typelib's CMake installs its Ruby bindings where RbConfig says, below
  # its prefix: lib/ruby/3.1.0 and lib/x86_64-linux-gnu/ruby/3.1.0 on
  # bookworm/amd64. A real Ruby requires both through env.sh alone.
  it "puts the target Ruby's folders below a compiled package's prefix on RUBYLIB" do
    dirs = Relspec::ReleaseSpec::Distributions::BUILTIN.fetch("bookworm").ruby_install_dirs("amd64")
    expect(dirs).to eq(%w[lib/ruby/3.1.0 lib/x86_64-linux-gnu/ruby/3.1.0])
    package("tools/typelib", [], ruby_dirs: dirs)
    { "lib/ruby/3.1.0/typelib.rb" => "require 'typelib_ruby'\nTYPELIB = :pure",
      "lib/x86_64-linux-gnu/ruby/3.1.0/typelib_ruby.rb" => "TYPELIB_RUBY = :ext" }.each do |path, code|
      FileUtils.mkdir_p(File.dirname(File.join(prefix("tools/typelib"), path)))
      File.write(File.join(prefix("tools/typelib"), path), code)
    end
    out, err, status = Open3.capture3({ "RUBYLIB" => nil }, "sh", "-c",
                                      ". #{prefix('tools/typelib')}/env.sh && ruby -e 'require \"typelib\"; p [TYPELIB, TYPELIB_RUBY]'")
    expect(status).to be_success, err
    expect(out).to eq("[:pure, :ext]\n")
    yml = YAML.safe_load(@files.fetch("env.yml"), permitted_classes: [Symbol])
    expect(yml.fetch("RUBYLIB").fetch(:values)).to include(*dirs.map { |dir| "#{prefix('tools/typelib')}/#{dir}" })
  end

  it "keeps a package the target's Ruby is unknown for on <prefix>/lib" do
    expect(Relspec::ReleaseSpec::Distribution.define("sid", "debian", %w[sid]).ruby_install_dirs("amd64")).to eq([])
    package("base/cmake", [])
    expect(@files.fetch("env.sh")).to include("export RUBYLIB=\"#{prefix('base/cmake')}/lib${RUBYLIB")
  end
end
