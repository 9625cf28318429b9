# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/gem_osdep_release"
require_relative "../../support/mid_update_archive"

# `relspec plan` reads its distribution's archive with the reader `relspec
# check` uses: a gem osdep taken from the archive (ruby-foo) is found in an
# archive served over HTTP on 127.0.0.1 in the middle of a mirror sync
# (MidUpdateArchive: by-hash right, canonical stale), and where no by-hash
# file saves it the plan stops with the one message apt would give. The
# release's gem_source is a closed port: a plan that does not find ruby-foo
# fails.
RSpec.describe "relspec plan on an archive in the middle of an update" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-plan-mid-update")
    GemOsdepRelease.build(@base, archive: "pristine", package: ["ruby-foo", "1.2.0-1"])
  end

  after(:all) { FileUtils.rm_rf(@base) if @base }

  after { @server&.stop }

  def plan(**options)
    archive = File.join(@base, "debian-#{options.hash.abs}")
    FileUtils.rm_rf(archive)
    FileUtils.cp_r(File.join(@base, "pristine"), archive)
    MidUpdateArchive.apply(archive, "bookworm", **options)
    @server = HttpServer.new(archive)
    FileUtils.mkdir_p(File.join(@base, "specs"))
    File.write(File.join(@base, "specs", "g.yml"),
               "release: g\nworkspace: ../ws/workspace\ntargets: { bookworm: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\ngem_source: http://127.0.0.1:1\n" \
               "distributions:\n  bookworm: { archive: { url: \"#{@server.url}\", trusted: true } }\n")
    relspec("plan", "specs/g.yml", chdir: @base, env: { "XDG_CACHE_HOME" => File.join(@base, "cache-#{options.hash.abs}") })
  end

  it "takes the gem from the by-hash index, reading no binary-all" do
    run = plan
    expect(run.exit_code).to eq(0), run.stderr
    expect(@server.requests.grep(%r{binary-amd64/})).to all(include("/by-hash/SHA256/"))
    expect(@server.requests.grep(/binary-all/)).to eq([])
  end

  it "stops with apt's word for a stale index when no by-hash file saves it" do
    run = plan(by_hash: false)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).to include("error[distribution-archive]: the archive of bookworm: #{@server.url}/dists/bookworm/" \
                                  "main/binary-amd64/Packages.gz does not match the SHA256 of the Release file (got ",
                                  "also when read again: the archive may be in the middle of an update (mirror sync in " \
                                  "progress?); try again later, or use another mirror")
    expect(run.stderr).not_to match(CliRunner::BACKTRACE)
  end
end
