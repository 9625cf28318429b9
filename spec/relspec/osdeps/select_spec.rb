# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/http_server"

# `relspec osdeps select` on a real reprepro repository, through the CLI.
RSpec.describe "relspec osdeps select" do
  # autoproj package => [Debian name, Depends, Provides]
  def packages
    {
      "base/cmake" => ["rock-rel-base-cmake", nil, nil],
      "base/types" => %w[rock-rel-base-types rock-rel-base-cmake rock-typekit],
      "base/logging" => ["rock-rel-base-logging", "rock-rel-base-cmake (>= 1.0)", nil],
      "drivers/iodrivers" => ["rock-rel-drivers-iodrivers", "rock-rel-base-types | rock-rel-base-logging", nil],
      "tools/monitor" => ["rock-rel-tools-monitor", "rock-rel-drivers-iodrivers, libc6", nil],
      "tools/typekit-user" => ["rock-rel-tools-typekit-user", "rock-typekit", nil],
      "data/typekit" => ["rock-rel-data-typekit", nil, "rock-typekit"],
      "gui/viewer" => ["rock-rel-gui-viewer", "rock-rel-base-logging", nil]
    }.freeze
  end

  around do |example|
    Dir.mktmpdir("relspec-select") do |dir|
      @dir = dir
      setup
      example.run
    end
  end

  def setup
    repository = AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: ["bionic"], architectures: ["amd64"])
    repository.add_many(packages.values.map { |deb, depends, provides| { name: deb, version: "1.0-1~bionic", arch: "amd64", depends: depends, provides: provides } },
                        codename: "bionic")
    data = File.join(@dir, "data")
    FileUtils.mkdir_p(data)
    File.write(File.join(data, "releases.yml"), "default: { separate_prefixes: true }\nbase-rel: ~\nrel: { depends_on: base-rel }\n")
    # the parent provides two packages, one of which the child overrides
    entry = ->(deb) { { "ubuntu,debian" => { "18.04,bionic,beaver" => deb } } }
    File.write(File.join(data, "base-rel-amd64.yml"),
               YAML.dump("base/cmake" => entry.call("rock-base-rel-base-cmake"), "legacy/only-parent" => entry.call("rock-base-rel-legacy")))
    File.write(File.join(data, "rel-amd64.yml"), YAML.dump(packages.transform_values { |deb, _, _| entry.call(deb) }))
  end

  def select(*extra)
    relspec("osdeps", "select", "--release", "rel", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
            "--data", "data", "--index", "repo/dists/bionic/main/binary-amd64/Packages.gz", "--output", "out", *extra, chdir: @dir)
  end

  def blacklist(text)
    File.write(File.join(@dir, "deb_blacklist.yml"), text)
    "deb_blacklist.yml"
  end

  def output(name)
    YAML.safe_load(File.read(File.join(@dir, "out", name)))
  end

  it "keeps everything, ancestors first and the release overriding them, without a blacklist" do
    run = select
    expect(run.exit_code).to eq(0), run.stderr
    osdeps = output("rock-osdeps.osdeps")
    expect(osdeps.keys).to eq((packages.keys + ["legacy/only-parent"]).sort)
    expect(osdeps["base/cmake"]).to eq("default" => "rock-rel-base-cmake")
    expect(osdeps["legacy/only-parent"]).to eq("default" => "rock-base-rel-legacy")
    expect(output("rock-osdeps.inactive")).to eq({})
  end

  it "disables a low-level package and exactly its transitive reverse dependencies" do
    run = select("--blacklist", blacklist("- base/cmake\n"))
    expect(run.exit_code).to eq(0), run.stderr
    inactive = output("rock-osdeps.inactive")
    # by hand: types and logging need cmake; iodrivers needs types or logging
    # (both off); monitor needs iodrivers; viewer needs logging. The typekit
    # user still has data/typekit providing rock-typekit.
    expect(inactive.keys).to eq(%w[base/cmake base/logging base/types drivers/iodrivers gui/viewer tools/monitor])
    expect(output("rock-osdeps.osdeps").keys).to eq(%w[data/typekit legacy/only-parent tools/typekit-user])
    expect(inactive["tools/monitor"]).to eq(["depends on drivers/iodrivers", "depends on base/logging", "depends on base/cmake",
                                             'blacklisted by "base/cmake" (deb_blacklist.yml:1:3)'])
  end

  it "keeps packages whose dependency has a surviving alternative or provider" do
    select("--blacklist", blacklist("- base/types\n"))
    expect(output("rock-osdeps.inactive").keys).to eq(["base/types"])
  end

  it "matches globs and regular expressions, and reports entries that match nothing" do
    run = select("--blacklist", blacklist("- \"gui/*\"\n- /^tools\\/mon/\n- simulation/**\n"))
    expect(output("rock-osdeps.inactive").keys).to eq(%w[gui/viewer tools/monitor])
    expect(run.stderr).to include('deb_blacklist.yml:3:3: warning[unmatched-blacklist]: "simulation/**" matches no package of rel')
  end

  it "reads the rock-osdeps package set's blacklist syntax: a plain name, else an unanchored regex" do
    # the package set README's own example
    run = select("--blacklist", blacklist("- base/types\n- ^orogen$\n- simulation/.*\n"))
    expect(run.exit_code).to eq(0), run.stderr
    expect(output("rock-osdeps.inactive").keys).to eq(["base/types"])
    expect(run.stderr).to include('deb_blacklist.yml:2:3: warning[unmatched-blacklist]: "^orogen$" matches no package')
    expect(run.stderr).not_to include("error")
  end

  it "warns where relspec's and the package set's readings of an entry differ, and disables both" do
    run = select("--blacklist", blacklist("- drivers/.*\n- /^gui/\n- \"tools/*\"\n"))
    expect(run.exit_code).to eq(0), run.stderr
    expect(output("rock-osdeps.inactive").keys).to eq(%w[drivers/iodrivers gui/viewer tools/monitor tools/typekit-user])
    expect(run.stderr.lines.grep(/blacklist-reading/)).to eq([
      'deb_blacklist.yml:1:3: warning[blacklist-reading]: "drivers/.*": relspec reads it as a glob (matches nothing), ' \
      "the rock-osdeps package set as an unanchored regular expression (drivers/iodrivers): both are disabled\n",
      'deb_blacklist.yml:2:3: warning[blacklist-reading]: "/^gui/": relspec reads it as a regex (gui/viewer), ' \
      "the rock-osdeps package set as a name (matches nothing): both are disabled\n"
    ])
  end

  {
    "base/cmake: yes\n" => "deb_blacklist.yml:1:1: error[wrong-type]: the blacklist must be a list of package names or patterns",
    "- base/cmake\n- /tools(/\n" => "deb_blacklist.yml:2:3: error[blacklist-regex]: invalid regular expression /tools(/",
    "- [base\n" => "deb_blacklist.yml:1:3: error[yaml-syntax]"
  }.each do |text, message|
    it "refuses a malformed blacklist (#{text.lines.last.strip}) and leaves the previous files untouched" do
      expect(select.exit_code).to eq(0)
      before = File.binread(File.join(@dir, "out", "rock-osdeps.osdeps"))
      run = select("--blacklist", blacklist(text))
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to start_with(message)
      expect(run.stderr).not_to match(/\.rb:\d+:in /)
      expect(File.binread(File.join(@dir, "out", "rock-osdeps.osdeps"))).to eq(before)
      expect(Dir.children(File.join(@dir, "out")).sort).to eq(%w[rock-osdeps.inactive rock-osdeps.osdeps])
    end
  end

  it "reads the index from the repository URL too" do
    server = HttpServer.new(File.join(@dir, "repo"))
    run = relspec("osdeps", "select", "--release", "rel", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
                  "--data", "data", "--index", server.url, "--trusted", "--output", "out",
                  "--blacklist", blacklist("- base/logging\n"), chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(output("rock-osdeps.inactive").keys).to eq(%w[base/logging gui/viewer])
  ensure
    server&.stop
  end

  it "reads the published Rock release data" do
    fixtures = File.expand_path("../shared/fixtures/rock-osdeps", CliRunner::ROOT)
    need_fixture(File.directory?(fixtures), "the real Rock osdeps files (#{fixtures}) are not beside this checkout")

    run = relspec("osdeps", "select", "--release", "master-20.06", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
                  "--data", fixtures, "--output", File.join(@dir, "rock"))
    expect(run.exit_code).to eq(0), run.stderr
    osdeps = YAML.safe_load(File.read(File.join(@dir, "rock", "rock-osdeps.osdeps")))
    expect(osdeps["orogen"]).to eq("default" => "rock-master-20.06-ruby-orogen")
    expect(osdeps["tools/orocos.rb"]).to eq("default" => "rock-master-20.06-ruby-tools-orocos.rb")
    expect(osdeps.size).to be > 300
  end
end

# --timeout reaches the repository URLs select reads (Http::Download, as
# every download of relspec): a server that never answers costs three waits
# of --timeout per file asked (InRelease, then Release), not the default's
# 10 s each (a minute).
RSpec.describe "relspec osdeps select --timeout" do
  it "gives up on a repository URL that does not answer within it, three times" do
    Dir.mktmpdir("relspec-select-timeout") do |dir|
      server = HttpServer.new(dir)
      server.fail(%r{/dists/}, :stall, seconds: 4)
      File.write(File.join(dir, "releases.yml"), "rel: ~\n")
      File.write(File.join(dir, "rel-amd64.yml"), "base/ok:\n  ubuntu,debian:\n    18.04,bionic: rock-ok\n")
      started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
      run = relspec("osdeps", "select", "--release", "rel", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
                    "--data", dir, "--index", "#{server.url}/repo", "--trusted", "--timeout", "1", "--output", File.join(dir, "out"))
      elapsed = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
      expect(run.exit_code).to eq(1), run.stderr
      expect(run.stderr).to include("cannot read the index #{server.url}/repo: #{server.url}/repo/dists/bionic/InRelease: " \
                                    "no answer within 1 s per read (after 3 attempts")
      expect(elapsed).to be < 30
      expect(File.exist?(File.join(dir, "out"))).to be(false)
    ensure
      server&.stop
    end
  end
end

# The names a user's system resolves to reach autoproj's `apt-get install`
# (as root): read as the package set's init.rb reads them (Osdeps::Reader),
# where select once wrote whatever the file said.
RSpec.describe "relspec osdeps select with an osdeps file naming no Debian package" do
  it "refuses it, naming the file and the package, and writes nothing" do
    Dir.mktmpdir("relspec-select-names") do |dir|
      File.write(File.join(dir, "releases.yml"), "rel: ~\n")
      File.write(File.join(dir, "rel-amd64.yml"), "base/ok:\n  ubuntu,debian:\n    18.04,bionic: rock-ok\n" \
                                                  "base/evil:\n  ubuntu,debian:\n    18.04,bionic: \"-oAPT::Update=x\"\n" \
                                                  "gem:\n  gem: not_a_debian_name\n")
      run = relspec("osdeps", "select", "--release", "rel", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
                    "--data", dir, "--output", File.join(dir, "out"))
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("rel-amd64.yml: error[osdeps-file]: base/evil: \"-oAPT::Update=x\" is not a Debian package name")
      expect(run.stderr).not_to match(/\.rb:\d+:in /)
      expect(File.exist?(File.join(dir, "out"))).to be(false)
    end
  end
end

RSpec.describe "relspec osdeps select with a malformed releases.yml" do
  {
    "- rel\n" => "releases.yml: error[release-index]: is not a mapping of releases",
    "rel: base-rel\n" => 'releases.yml: error[release-index]: "rel": is not a mapping',
    "rel: { depends_on: ../../etc }\n" => 'releases.yml: error[release-index]: "rel": "../../etc" is not a release name',
    "base: { depends_on: rel }\nrel: { depends_on: base }\n" => "releases.yml: error[release-index]: depends_on cycle through rel"
  }.each do |index, message|
    it "refuses #{index.strip.inspect} with a clear message" do
      Dir.mktmpdir("relspec-releases-yml") do |dir|
        File.write(File.join(dir, "releases.yml"), index)
        File.write(File.join(dir, "rel-amd64.yml"), "{}\n")
        run = relspec("osdeps", "select", "--release", "rel", "--arch", "amd64", "--os", "ubuntu,debian:18.04,bionic",
                      "--data", dir, "--output", File.join(dir, "out"))
        expect(run.exit_code).to eq(1)
        expect(run.stderr).to include(message)
        expect(run.stderr).not_to match(/\.rb:\d+:in /)
      end
    end
  end
end
