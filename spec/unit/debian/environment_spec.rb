# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/environment"

# What a package installs to be used: env.sh, env.yml and relspec.yml
# (build_environment_spec.rb sources env.sh in a real shell).
RSpec.describe Relspec::Debian::Environment do
  let(:settings) do
    [{ "type" => "add_path", "name" => "OROGEN_PLUGIN_PATH", "values" => ["$PREFIX/share/orogen"] },
     { "type" => "set", "name" => "EVIL", "values" => ["$(rm -rf /)"] }]
  end

  it "sources the dependencies' env.sh, once per shell, and keeps only the settings the package set accepts" do
    environment = described_class.new(build_input(dependencies: [dependency("rock-r-a", "/opt/rock/r/rock-r-a")],
                                                  package: { environment: settings }))
    text = environment.env_sh
    expect(text).to include("if [ -z \"${RELSPEC_ENV_rock_r_pkg:-}\" ]; then\n",
                            "if [ -f /opt/rock/r/rock-r-a/env.sh ]; then . /opt/rock/r/rock-r-a/env.sh; fi\n",
                            "export OROGEN_PLUGIN_PATH=\"/opt/rock/r/rock-r-pkg/share/orogen${OROGEN_PLUGIN_PATH:+:$OROGEN_PLUGIN_PATH}\"\n",
                            "export GEM_PATH=\"/opt/rock/r/rock-r-pkg/gems${GEM_PATH:+:$GEM_PATH}\"\n")
    expect(text).not_to include("EVIL")
    expect(environment.env_yml).to include("OROGEN_PLUGIN_PATH:").and include("RUBYLIB:")
    expect(environment.env_yml).not_to include("EVIL")
  end

  it "puts the prefix's lib/ on RUBYLIB, and a compiled package's Ruby folders too" do
    cmake = described_class.new(build_input(ruby_dirs: ["lib/ruby/vendor_ruby"])).env_sh
    expect(cmake).to include("export RUBYLIB=\"/opt/rock/r/rock-r-pkg/lib:/opt/rock/r/rock-r-pkg/lib/ruby/vendor_ruby${")
    ruby = described_class.new(build_input(build_type: "ruby", ruby_dirs: ["lib/ruby/vendor_ruby"])).env_sh
    expect(ruby).to include("export RUBYLIB=\"/opt/rock/r/rock-r-pkg/lib${")
  end

  it "records the package, its release, prefix and the dependencies' prefixes in relspec.yml" do
    environment = described_class.new(build_input(dependencies: [dependency("rock-r-a", "/opt/rock/r/rock-r-a")]))
    expect(YAML.safe_load(environment.relspec_yml))
      .to eq("package" => "pkg", "release" => "r", "prefix" => "/opt/rock/r/rock-r-pkg",
             "dependencies" => ["/opt/rock/r/rock-r-a"])
  end
end
