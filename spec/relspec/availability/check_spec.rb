# frozen_string_literal: true

require "spec_helper"
require "json"

# `relspec check` and compile's check, end to end on the demo workspace:
# against this machine's own bookworm apt lists (what bin/setup's
# apt-get update leaves in /var/lib/apt/lists), and against a local
# Launchpad-shaped server for an Ubuntu target.
RSpec.describe "relspec check" do
  ARCH = `dpkg --print-architecture`.strip

  before(:all) do
    @dir = Dir.mktmpdir("relspec-check")
    @fixture = ReleaseFixture.new(@dir)
    @fixture.spec("host", <<~YAML, workspace: :checkouts)
      targets: { bookworm: [#{ARCH}] }
      maintainer: Demo <demo@example.org>
      distributions:
        bookworm: { archive: { host: true } }
    YAML
    @osdeps = File.join(@fixture.builder.root, "package_sets", @fixture.builder.package_set_name,
                        "#{@fixture.builder.package_set_name}.osdeps")
    @original = File.read(@osdeps)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after { File.write(@osdeps, @original) }

  # The Debian side of the boost osdep renamed to a name bookworm does not have.
  def rename_boost
    File.write(@osdeps, @original.sub(/(debian:\n\s+buster: libboost1.67-all-dev\n\s+default: )libboost-dev/,
                                      "\\1libboost-system1.67-dev"))
    expect(File.read(@osdeps)).to include("default: libboost-system1.67-dev")
  end

  it "passes for the demo release on bookworm against this machine's apt lists" do
    run = relspec("check", "specs/host.yml", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(run.stdout).to match(%r{\Abookworm/#{ARCH}: \d+ relations checked \(apt: this machine's apt lists\)\n\z})
  end

  it "reports a renamed osdep with the packages that need it and a similar existing name, and exits 1" do
    rename_boost
    run = relspec("check", "specs/host.yml", chdir: @dir)
    expect(run.exit_code).to eq(1), run.stderr
    expect(run.stdout).to include("1 missing")
    row = run.stdout.lines.find { |line| line.include?("libboost-system1.67-dev") }
    expect(row).to match(%r{\Abookworm/#{ARCH}\s+libboost-system1.67-dev\s+base/types, drivers/iodrivers_base\s+did you mean libboost-system1\.\d+-dev\?})

    json = JSON.parse(relspec("check", "specs/host.yml", "--format", "json", chdir: @dir).stdout)
    expect(json["missing"]).to match([a_hash_including("target" => "bookworm/#{ARCH}", "name" => "libboost-system1.67-dev",
                                                       "needed_by" => %w[base/types drivers/iodrivers_base],
                                                       "hint" => a_string_matching(/\Alibboost-system1\.\d+-dev\z/))])
    markdown = relspec("check", "specs/host.yml", "--format", "markdown", chdir: @dir).stdout
    expect(markdown).to include("| bookworm/#{ARCH} | `libboost-system1.67-dev` | base/types, drivers/iodrivers_base | `libboost-system1.")
  end

  it "makes compile refuse the release (writing nothing) unless --no-check" do
    rename_boost
    out = File.join(@dir, "refused")
    run = relspec("compile", "specs/host.yml", "--out", "refused", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("OS dependencies are missing", "libboost-system1.67-dev", "--no-check")
    expect(run.stderr).not_to include("Traceback", ".rb:")
    expect(File.exist?(out)).to be(false)
    forced = relspec("compile", "specs/host.yml", "--out", "refused", "--no-check", chdir: @dir)
    expect(forced.exit_code).to eq(0), forced.stderr
    expect(Dir.glob(File.join(out, "host", "bookworm-#{ARCH}", "*"))).not_to be_empty
  end

  it "rejects a target the release does not have, and an archive that is both host and a path" do
    run = relspec("check", "specs/host.yml", "--target", "bionic/amd64", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: bionic/amd64 is not a target of host (bookworm/#{ARCH})\n")
    @fixture.spec("both", "targets: { bookworm: [amd64] }\ndistributions:\n  bookworm: { archive: { host: true, path: /srv } }\n")
    both = relspec("check", "specs/both.yml", chdir: @dir)
    expect(both.exit_code).to eq(1)
    expect(both.stderr).to include("specs/both.yml:5:", "error[archive-host]", "sets host: true and path")
  end

  context "with an Ubuntu target and Launchpad" do
    # Everything the demo's jammy packages ask for except the motif library
    # of tools/legacy (it has a libmotif3-dev, to be suggested instead).
    PUBLISHED = %w[debhelper cmake autoconf automake libtool ruby ruby-dev git libboost-all-dev libeigen3-dev
                   libyaml-cpp-dev ruby-nokogiri].freeze

    before(:all) do
      @server = LaunchpadServer.new({ "jammy/amd64" => PUBLISHED + %w[libmotif3-dev] })
      @fixture.spec("lp", "targets: { jammy: [amd64] }\nmaintainer: Demo <demo@example.org>\n", workspace: :checkouts)
      @cache = Dir.mktmpdir("relspec-check-cache")
    end

    after(:all) do
      @server.stop
      FileUtils.rm_rf(@cache)
    end

    def run_in_cache(*args)
      stdout, stderr, status = Open3.capture3({ "XDG_CACHE_HOME" => @cache }, RbConfig.ruby, CliRunner::EXE, *args,
                                              chdir: @dir, stdin_data: "")
      CliRunner::Run.new(stdout: stdout, stderr: stderr, status: status)
    end

    it "asks one question per distinct name, none again within the TTL, and compile answers from the cache" do
      run = run_in_cache("check", "specs/lp.yml", "--source", "launchpad", "--launchpad-url", @server.base)
      expect(run.exit_code).to eq(1), run.stderr
      expect(run.stdout).to match(%r{^jammy/amd64\s+libmotif-dev\s+tools/legacy\s+did you mean libmotif3-dev\?})
      questions = @server.requests.reject { |query| query["exact_match"] == "false" } # hints are extra questions
      expect(questions.map { |query| query["binary_name"] }.sort).to eq((PUBLISHED + ["libmotif-dev"]).sort)

      @server.requests.clear
      again = run_in_cache("check", "specs/lp.yml", "--launchpad-url", @server.base)
      expect(again.stdout).to include("jammy/amd64: 13 relations checked, 1 missing (launchpad: #{@server.base})")
      expect(@server.requests.reject { |query| query["exact_match"] == "false" }).to be_empty

      compile = run_in_cache("compile", "specs/lp.yml", "--out", "lp-out", "--launchpad-url", @server.base)
      expect(compile.exit_code).to eq(1)
      expect(compile.stderr).to include("libmotif-dev")
      expect(@server.requests.reject { |query| query["exact_match"] == "false" }).to be_empty
    end

    it "notes once, without refusing, when compile has no answer for a target" do
      run = run_in_cache("compile", "specs/lp.yml", "--out", "lp-note", "--launchpad-url", "#{@server.base}/elsewhere")
      expect(run.exit_code).to eq(0), run.stderr
      expect(run.stdout.lines.grep(/^note:/)).to eq(["note: OS dependencies not checked on jammy/amd64 " \
                                                     "(not in the cache; run relspec check)\n"])
      again = run_in_cache("compile", "specs/lp.yml", "--out", "lp-note", "--launchpad-url", "#{@server.base}/elsewhere")
      expect(again.stdout).to match(/\Alp: nothing changed/)
    end
  end
end
