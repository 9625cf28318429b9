# frozen_string_literal: true

require "spec_helper"
require "relspec/release_specs"
require "relspec/mirror/sources"
require "relspec/target"
require_relative "../../support/mid_update_archive"

# What `relspec mirror` reads of a distribution's archive, with the reader
# plan and check use: an archive served over HTTP on 127.0.0.1 in the
# middle of a mirror sync (MidUpdateArchive) gives its by-hash index and no
# binary-all; where no by-hash file saves it, `relspec mirror` stops with
# apt's message and exit 1.
RSpec.describe "relspec mirror on an archive in the middle of an update" do
  around do |example|
    Dir.mktmpdir("relspec-mirror-mid-update") do |dir|
      @dir = dir
      example.run
    ensure
      @server&.stop
    end
  end

  # The release's own repository (one package), the distribution's archive
  # caught mid-update, and the spec; returns the spec's path.
  def release(**options)
    AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: ["trixie"], architectures: ["amd64"])
                        .add("rock-m-one", "1.0-1~trixie", codename: "trixie", arch: "amd64", depends: "data-common")
    archive = File.join(@dir, "debian")
    AptRepositoryBuilder.new(archive, codenames: ["trixie"], architectures: ["amd64"])
                        .add_many([{ name: "libc6", version: "2.41-12", arch: "amd64" },
                                   { name: "data-common", version: "2-1", arch: "all" }], codename: "trixie")
    MidUpdateArchive.apply(archive, "trixie", **options)
    @server = HttpServer.new(archive)
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "m.yml"), <<~YAML)
      release: m
      workspace: ../ws
      targets: { trixie: [amd64] }
      repository: { path: ../repo, trusted: true }
      distributions:
        trixie: { archive: { url: "#{@server.url}", trusted: true } }
    YAML
    File.join(@dir, "specs", "m.yml")
  end

  it "reads the distribution's by-hash index, with its Architecture: all packages, and no binary-all" do
    resolution = Relspec::ReleaseSpec.resolve(release)
    read = Relspec::Mirror::Sources.new(resolution, timeout: 5).read(Relspec::Target.parse("trixie/amd64"))
    expect(read.index.names.sort).to eq(%w[data-common libc6 rock-m-one])
    expect(read.index["data-common"].origin.distribution).to be(true)
    expect(@server.requests.grep(%r{binary-amd64/})).to all(include("/by-hash/SHA256/"))
    expect(@server.requests.grep(/binary-all/)).to eq([])
  end

  it "stops with apt's message when the canonical index is stale and there is no by-hash file" do
    release(by_hash: false)
    run = relspec("mirror", "specs/m.yml", "--out", "out", chdir: @dir,
                                                           env: { "XDG_CACHE_HOME" => File.join(@dir, "cache") })
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to start_with("relspec: error: #{@server.url}/dists/trixie/main/binary-amd64/Packages.gz does " \
                                     "not match the SHA256 of the Release file (got ")
    expect(run.stderr).to end_with("also when read again: the archive may be in the middle of an update (mirror sync " \
                                   "in progress?); try again later, or use another mirror\n")
    expect(Dir.exist?(File.join(@dir, "out", "pool"))).to be(false)
  end
end
