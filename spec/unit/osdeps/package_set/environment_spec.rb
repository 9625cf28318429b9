# frozen_string_literal: true

require_relative "../../unit_helper"
require "autoproj"
require "relspec/osdeps/package_set/environment"

# The installed packages' env.yml in a workspace's environment (a real
# Autoproj::Environment): applied in order, refused outside /opt/rock.
RSpec.describe RelspecPackageSet::Environment do
  it "applies each operation to the workspace's environment" do
    env = Autoproj::Environment.new
    described_class.new([[:set, "ROCK_PREFIX", "/opt/rock/r"], [:add_path, "PATH", "/opt/rock/r/bin"]]).apply(env)
    expect(env.environment["ROCK_PREFIX"]).to eq(["/opt/rock/r"])
    expect(env.environment["PATH"]).to include("/opt/rock/r/bin")
  end

  it "refuses an env.yml outside the prefix, before reading it" do
    Dir.mktmpdir do |dir|
      path = File.join(dir, "env.yml")
      File.write(path, "LD_PRELOAD:\n  :type: :set\n  :values: [/tmp/x.so]\n")
      expect { described_class.operations(path) }
        .to raise_error(Autoproj::ConfigError, %r{#{Regexp.escape(path)}: is #{Regexp.escape(File.realpath(path))}, outside /opt/rock\z})
    end
  end
end
