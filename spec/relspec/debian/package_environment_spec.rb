# frozen_string_literal: true

require "spec_helper"
require "open3"
require "yaml"
require "relspec/debian/debian_dir"
require "relspec/catalog/package"

# A package set's own environment settings of a package (typelib's
# `pkg.env_set 'TYPELIB_PLUGIN_PATH', File.join(pkg.prefix, 'lib', 'typelib')`)
# reach the package's env.sh and env.yml with the release's prefix: without
# them typelib's installed plugins are not found through the packages'
# environment as they are in a source-built workspace.
RSpec.describe "the package set's environment in env.sh and env.yml" do
  prefix = "/opt/rock/r/rock-r-typelib"

  def render(environment)
    package = Relspec::Catalog::Package.new(
      name: "typelib", package_set: "set", build_type: "cmake", commit_time: "2021-03-04T05:06:07Z",
      source_dir: "src/typelib", environment: environment,
      vcs: Relspec::Catalog::Vcs.from_h("type" => "git", "url" => "https://example.org/t.git", "commit" => "a" * 40)
    )
    input = Relspec::Debian::BuildInput.new(
      package: package, deb_name: "rock-r-typelib", upstream: "0.1", codename: "bookworm", release: "r",
      maintainer: "M <m@example.org>", install_dir: "/opt/rock/r/rock-r-typelib", dependencies: [], apt: [],
      gems: [], gem: nil, debhelper_compat: 13
    )
    Relspec::Debian::DebianDir.render(input, version: "0.1-1~bookworm").transform_values(&:first)
  end

  # The variables after sourcing env.sh in sh, from an environment with +env+.
  def sourced(env_sh, env = {})
    script = ". /dev/stdin <<'ENV'\n#{env_sh}ENV\nprintf '%s\\n' \"$TYPELIB_PLUGIN_PATH\" \"$QT_PLUGIN_PATH\" \"$CMAKE_PREFIX_PATH\""
    output, status = Open3.capture2({ "TYPELIB_PLUGIN_PATH" => nil, "QT_PLUGIN_PATH" => nil }.merge(env), "sh", "-c", script)
    raise output unless status.success?

    output.lines.map(&:chomp)
  end

  environment = [
    { "type" => "set", "name" => "TYPELIB_PLUGIN_PATH", "values" => ["$PREFIX/lib/typelib"] },
    { "type" => "add_path", "name" => "QT_PLUGIN_PATH", "values" => ["$PREFIX/share/a", "$PREFIX/share/b"] },
    { "type" => "add_path", "name" => "CMAKE_PREFIX_PATH", "values" => ["$PREFIX/cmake"] }
  ]

  it "sets and adds the variables in env.sh with the release's prefix" do
    env_sh = render(environment)["env.sh"]
    expect(sourced(env_sh)).to eq(["#{prefix}/lib/typelib", "#{prefix}/share/a:#{prefix}/share/b",
                                   "#{prefix}/cmake:#{prefix}"])
    # set replaces, add_path prepends to what the shell had
    expect(sourced(env_sh, "TYPELIB_PLUGIN_PATH" => "/old", "QT_PLUGIN_PATH" => "/old"))
      .to eq(["#{prefix}/lib/typelib", "#{prefix}/share/a:#{prefix}/share/b:/old", "#{prefix}/cmake:#{prefix}"])
  end

  it "writes them into env.yml in the package set's format, one entry per variable" do
    data = YAML.safe_load(render(environment)["env.yml"], permitted_classes: [Symbol])
    expect(data["TYPELIB_PLUGIN_PATH"]).to eq(type: :set, values: ["#{prefix}/lib/typelib"], priority: 0)
    # the value searched first is written last (autoproj prepends one after the other)
    expect(data["QT_PLUGIN_PATH"]).to eq(type: :add_path, values: ["#{prefix}/share/b", "#{prefix}/share/a"], priority: 0)
    expect(data["CMAKE_PREFIX_PATH"][:values]).to eq([prefix, "#{prefix}/cmake"])
  end

  it "leaves out what would be shell code in env.sh" do
    hostile = [{ "type" => "set", "name" => "X; rm -rf /", "values" => ["a"] },
               { "type" => "set", "name" => "Y", "values" => ["$(id)"] }]
    files = render(hostile)
    expect(files["env.sh"]).not_to include("rm -rf")
    expect(files["env.sh"]).not_to include("$(id)")
    expect(files["env.yml"]).not_to include("rm -rf")
  end

  # What relspec's package set would refuse (Osdeps::Trust) never reaches
  # env.yml: it would refuse the whole release for it.
  it "writes only what the package set accepts: documented variables, paths below the prefix, plain words" do
    settings = [{ "type" => "set", "name" => "LD_PRELOAD", "values" => ["$PREFIX/lib/evil.so"] },
                { "type" => "add_path", "name" => "UNKNOWN_PATH", "values" => ["$PREFIX/x"] },
                { "type" => "set", "name" => "Syskit_DIR", "values" => ["/home/maintainer/ws/tools/syskit/cmake"] },
                { "type" => "set", "name" => "TYPELIB_CXX_LOADER", "values" => ["castxml"] },
                { "type" => "set", "name" => "ROCK_PREFIX", "values" => ["$PREFIX/share/rock"] }]
    data = YAML.safe_load(render(settings)["env.yml"], permitted_classes: [Symbol])
    expect(data.keys).not_to include("LD_PRELOAD", "UNKNOWN_PATH", "Syskit_DIR")
    expect(data["TYPELIB_CXX_LOADER"]).to eq(type: :set, values: ["castxml"], priority: 0)
    expect(data["ROCK_PREFIX"]).to eq(type: :set, values: ["#{prefix}/share/rock"], priority: 0)
  end

  it "writes nothing more for a package without settings" do
    expect(render([])["env.sh"]).not_to include("TYPELIB")
  end
end
