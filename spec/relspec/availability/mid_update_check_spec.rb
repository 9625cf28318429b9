# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/mid_update_archive"

# `relspec check` for trixie against a Debian-shaped archive served over
# HTTP on 127.0.0.1 while it is in the middle of a mirror sync
# (MidUpdateArchive): it answers where apt would (by-hash files, no
# binary-all), and where apt would fail too (no by-hash file, the canonical
# one stale) it says so once, after one more reading, and exits 1.
RSpec.describe "relspec check on an archive in the middle of an update" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-mid-update")
    builder = WorkspaceBuilder.new(@base)
    builder.package("base/app", type: :cmake, date: "2020-06-02T10:00:00Z", osdeps: %w[libx])
    builder.osdeps("libx:\n  debian: libx-dev\n")
    builder.create
    FileUtils.mkdir_p(File.join(@base, "specs"))
  end

  after(:all) { FileUtils.rm_rf(@base) if @base }

  after { @server&.stop }

  # A trixie archive holding what base/app needs, caught mid-update, and a
  # spec reading it.
  def serve(**options)
    path = @archive = File.join(@base, "debian-#{options.hash.abs}")
    FileUtils.rm_rf(path)
    AptRepositoryBuilder.new(path, codenames: ["trixie"], architectures: ["amd64"])
                        .add_many([{ name: "cmake", version: "3.31.6-2", arch: "amd64" },
                                   { name: "libx-dev", version: "1.0-1", arch: "amd64" },
                                   { name: "ruby-dev", version: "1:3.3+b1", arch: "amd64" },
                                   { name: "debhelper", version: "13.24.2", arch: "all", provides: "debhelper-compat (= 13)" }],
                                  codename: "trixie")
    MidUpdateArchive.apply(path, "trixie", **options)
    @server = HttpServer.new(path)
    File.write(File.join(@base, "specs", "app.yml"), <<~YAML)
      release: app
      maintainer: Rock Packaging <rock@example.org>
      workspace: ../workspace
      select: [base/app]
      targets: { trixie: [amd64] }
      distributions:
        trixie: { archive: { url: "#{@server.url}", trusted: true } }
    YAML
  end

  def check(command = "check", *args)
    relspec(command, "specs/app.yml", *args, chdir: @base,
                                             env: { "XDG_CACHE_HOME" => File.join(@base, "cache-#{rand(1 << 30)}") })
  end

  it "reads the by-hash files, and not the stale binary-all, where apt would" do
    serve
    run = check
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(run.stdout).to match(%r{\Atrixie/amd64: [1-9]\d* relations checked \(apt: #{Regexp.escape(@server.url)}\)\n\z})
    expect(@server.requests.grep(%r{binary-amd64/})).to all(include("/by-hash/SHA256/"))
    expect(@server.requests.grep(/binary-all/)).to eq([])
    compiled = check("compile", "--out", "out-by-hash")
    expect(compiled.exit_code).to eq(0), compiled.stderr
  end

  it "says once that the mirror may be syncing when the canonical file is stale and there is no by-hash file" do
    serve(by_hash: false)
    run = check
    expect(run.exit_code).to eq(1)
    expect(run.stderr).not_to match(CliRunner::BACKTRACE)
    listed = File.read(File.join(@archive, "dists", "trixie", "Release"))[%r{^ \h{64} +(\d+) main/binary-amd64/Packages.gz$}, 1]
    stale = File.size(File.join(@archive, "dists", "trixie", "main", "binary-amd64", "Packages.gz"))
    expect(run.stdout).to eq("trixie/amd64: could not be checked: #{@server.url}/dists/trixie/main/binary-amd64/" \
                             "Packages.gz does not match the SHA256 of the Release file (got #{stale} bytes, expected " \
                             "#{listed}), also when read again: the archive may be in the middle of an update (mirror " \
                             "sync in progress?); try again later, or use another mirror (apt: #{@server.url})\n")
    # by hash (missing), by name; the same once more; nothing after
    expect(@server.requests.grep(%r{binary-amd64/}).map { |path| path[/by-hash|Packages\.gz\z/] })
      .to eq(%w[by-hash Packages.gz by-hash Packages.gz])
  end

  it "makes compile's check refuse the release, writing nothing, with the same message" do
    serve(by_hash: false)
    run = check("compile", "--out", "out-stale")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("could not be checked: #{@server.url}/dists/trixie/main/binary-amd64/Packages.gz " \
                                  "does not match the SHA256 of the Release file", "(mirror sync in progress?)")
    expect(run.stderr).not_to match(CliRunner::BACKTRACE)
    expect(File.exist?(File.join(@base, "out-stale"))).to be(false)
  end

  it "refuses a Release file whose listed digest is no SHA256 before it names a file to fetch" do
    serve
    release = File.join(@archive, "dists", "trixie", "Release")
    File.write(release, File.read(release).sub(%r{^ \h{64}( +\d+ main/binary-amd64/Packages.gz)$}, ' ../../../../etc/passwd\1'))
    run = check
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("trixie/amd64: could not be checked: #{@server.url}/dists/trixie/Release: the SHA256 of " \
                             "main/binary-amd64/Packages.gz is not 64 hex digits (../../../../etc/passwd): a malformed " \
                             "Release file (apt: #{@server.url})\n")
    expect(@server.requests.grep(/passwd|binary-amd64/)).to eq([])
  end
end
