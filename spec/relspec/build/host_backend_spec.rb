# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

# The host backend installs nothing: a build-dependency missing on this
# machine fails the build, named, before dpkg-buildpackage runs.
RSpec.describe "relspec build --backend host" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-host")
    @release = BuildRelease.new(@dir, "hb")
    @release.osdeps("absent:\n  debian: relspec-test-absent-package\n")
    @release.package("base/needs", osdeps: ["absent"])
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  it "names a build-dependency missing on this machine" do
    run = relspec("build", "specs/hb.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(1)
    source = @release.source("base/needs")
    record = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][source]
    expect(record["status"]).to eq("failed")
    expect(record["reason"]).to eq("#{source}: build-dependencies missing on this machine: relspec-test-absent-package " \
                                   "(relspec looked at the packages installed here, as dpkg-checkbuilddeps does; " \
                                   "install them, or build with --backend sbuild), see logs/#{source}.log")
    expect(run.stdout).to include("bookworm/amd64: 0 built, 0 already built, 1 failed, 0 skipped")
    expect(File.read(File.join(@release.target_dir, "logs", "#{source}.log"))).not_to include("dpkg-buildpackage")
  end

  it "refuses a release that was not compiled, saying what to run" do
    run = relspec("build", "specs/hb.yml", "--out", "elsewhere", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: #{File.join(@dir, 'elsewhere/hb/bookworm-amd64/plan.yml')} does not " \
                             "exist: run `relspec compile` first\n")
  end

  it "refuses a target the release does not have" do
    run = relspec("build", "specs/hb.yml", "--out", "out", "--backend", "host", "--target", "trixie/amd64", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: hb has no target trixie/amd64 (targets: bookworm/amd64)\n")
  end
end
