# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../support/toolchain_release"
require_relative "../support/installed_system"

# The Rock toolchain from the REAL package sets (rock.core +
# orocos.toolchain): typelib, RTT (CORBA with omniORB, as orocos.toolchain
# chooses), rtt_typelib, metaruby, orogen, orogen_metadata,
# service_discovery, base/orogen/std and base/types, each compiled by relspec
# and built in dependency order (sbuild in clean chroots unless
# RELSPEC_TOOLCHAIN_BACKEND=host), then installed with apt into a clean
# bookworm system. There, through the packages' env.sh only, a user's own
# oroGen component (spec/fixtures/orogen_component) is generated with the
# packaged orogen — its typekit from base/types' header by typelib's castxml
# importer — built with CMake, its deployment started, and a client writes a
# sample to its input port and reads the result from its output port over
# RTT's CORBA transport; typelib from Ruby imports a header with base types
# and loads the installed typekit registries.
#
# bin/test runs it in its chroot process with the host backend (about 22 min
# there, beside the rest of the suite); bin/toolchain-acceptance runs it with
# sbuild and RELSPEC_TOOLCHAIN_TYPES=1: SISL, base/types with it and
# base/orogen/types built too, and a second component, on
# /base/samples/RigidBodyState from base/orogen/types' typekit, run (outside
# CI: base/orogen/types alone is a 13-16 minute build; docs/performance.md).
RSpec.describe "a user's oroGen component on the packaged Rock toolchain" do
  FIXTURE = File.expand_path("../fixtures/orogen_component", __dir__)
  RBS_FIXTURE = File.expand_path("../fixtures/orogen_rbs_component", __dir__)
  TYPES = ENV["RELSPEC_TOOLCHAIN_TYPES"] == "1"

  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @dir = ENV.fetch("RELSPEC_TOOLCHAIN_DIR") { Dir.mktmpdir("relspec-toolchain") }
    @release = if TYPES
                 ToolchainRelease.new(@dir, select: ToolchainRelease::TYPES_SELECTION, sisl: true)
               else
                 ToolchainRelease.new(@dir)
               end
    @release.write
    backend = ENV.fetch("RELSPEC_TOOLCHAIN_BACKEND", "sbuild")
    @compile = relspec("compile", "specs/rock.yml", "--out", "out", "--quiet", chdir: @dir)
    raise "compile failed: #{@compile.stderr}" unless @compile.exit_code.zero?

    # the clean system's tarball, which sbuild's builds use too
    prepare = relspec("build", "specs/rock.yml", "--out", "out", "--prepare", chdir: @dir)
    raise "prepare failed: #{prepare.stderr}" unless prepare.exit_code.zero?

    @build = relspec("build", "specs/rock.yml", "--out", "out", "--backend", backend, "--jobs", "2", chdir: @dir)
    @results = YAML.safe_load_file(File.join(@release.target_dir, "build-results.yml"))
    raise "build failed:\n#{@build.stdout}#{@build.stderr}#{failed_logs}" unless @build.exit_code.zero?

    debs = @results.fetch("packages").values.flat_map { |record| record.fetch("files").map { |file| file.fetch("name") } }
                   .grep(/[.]deb\z/).grep_v(/-dbgsym_/).map { |name| File.join(@release.target_dir, name) }
    @system = InstalledSystem.new(File.join(CliRunner::CACHE, "relspec", "chroots", "bookworm-amd64.tar.zst"),
                                  File.join(@dir, "system"))
    # the user's tools: a compiler, CMake and pkg-config, not dependencies of the release
    @system.install(debs, packages: %w[build-essential cmake pkg-config])
    FileUtils.cp_r(FIXTURE, @system.path("tmp/orogen_component"))
    @session, status = @system.run("bash /tmp/orogen_component/user_session.sh /tmp/orogen_component /opt/rock/rock/rock-rock")
    raise "the user's session failed:\n#{@session}" unless status.success?
    next unless TYPES

    FileUtils.cp_r(RBS_FIXTURE, @system.path("tmp/orogen_rbs_component"))
    @rbs_session, status = @system.run("for env in /opt/rock/rock/*/env.sh; do . \"$env\"; done; " \
                                       "bash /tmp/orogen_rbs_component/user_session.sh /tmp/orogen_rbs_component")
    raise "the RigidBodyState session failed:\n#{@rbs_session}" unless status.success?
  end

  after(:all) { FileUtils.rm_rf(@dir) unless ENV["RELSPEC_TOOLCHAIN_DIR"] }

  def failed_logs
    @results.fetch("packages").values.select { |record| record["status"] == "failed" }.map do |record|
      "\n--- #{record['log']}:\n#{File.readlines(File.join(@release.target_dir, record['log'])).last(60).join}"
    end.join
  end

  it "builds the chain in dependency order" do
    order = YAML.safe_load_file(File.join(@release.target_dir, "plan.yml")).fetch("builds").map { |entry| entry["package"] }
    chain = %w[typelib rtt rtt_typelib orogen base/orogen/std]
    chain += %w[base/orogen/types] if TYPES
    expect(order & chain).to eq(chain.sort_by { |name| order.index(name) })
    expect(order.index("typelib")).to be < order.index("rtt_typelib")
    expect(order.index("rtt")).to be < order.index("rtt_typelib")
    expect(order.index("orogen")).to be < order.index("base/orogen/std")
    expect(order.index("external/sisl")).to be < order.index("base/types") if TYPES
    expect(@results.fetch("packages").values.map { |record| record["status"] }.uniq).to eq(["built"])
  end

  it "runs the user's deployment and carries a sample through its ports over CORBA" do
    # 21 us written to the task's input, doubled by its updateHook
    expect(@session[/^== deployment\n.*?(?=^== typelib)/m]).to match(/^out: 42 us$/)
  end

  it "imports a user's header with base types through typelib's castxml importer" do
    expect(@session).to include("header: UserSample time,weights,history\n")
  end

  it "loads the installed typekit registries: base/orogen/std's and the user's" do
    # the user's session sources base/orogen/std's and base/types' env.sh only,
    # so its typekit holds /base/Time even where base/orogen/types is installed
    expect(@session).to include("std typekit: /std/string 8\n", "user typekit: /base/Time microseconds\n")
  end

  if TYPES
    it "runs a component on /base/samples/RigidBodyState from base/orogen/types' typekit over CORBA" do
      # position (1 2 3) at 21 us written to the task's input, doubled by its updateHook
      expect(@rbs_session).to match(/^rbs out: 2 4 6 at 21 us$/)
    end
  end
end
