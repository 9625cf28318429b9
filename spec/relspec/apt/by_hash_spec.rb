# frozen_string_literal: true

require "spec_helper"
require "relspec/apt/repository"
require "relspec/availability/apt_source"
require "relspec/plan/target"
require_relative "../../support/mid_update_archive"

# A Debian archive in the middle of a mirror sync (MidUpdateArchive), served
# over HTTP on 127.0.0.1 and read as apt reads it: by-hash files first,
# binary-all not at all where the Release file says its packages are in
# binary-<arch>; a mismatch that stays after one more reading is said as apt
# says it.
RSpec.describe "an archive in the middle of an update" do
  around do |example|
    Dir.mktmpdir("relspec-by-hash") do |dir|
      @dir = dir
      example.run
    ensure
      @server&.stop
    end
  end

  def archive(**options)
    path = File.join(@dir, "debian")
    builder = AptRepositoryBuilder.new(path, codenames: ["trixie"], architectures: ["amd64"])
    builder.add_many([{ name: "cmake", version: "3.31.6-2", arch: "amd64" },
                      { name: "data-common", version: "2-1", arch: "all" },
                      { name: "debhelper", version: "13.24.2", arch: "all", provides: "debhelper-compat (= 13)" }],
                     codename: "trixie")
    MidUpdateArchive.apply(path, "trixie", **options)
    @server = HttpServer.new(path)
  end

  def reader(**options)
    Relspec::Apt::Repository.new(Relspec::Apt::Fetcher.new(@server.url, timeout: 5), trusted: true, retry_pause: 0, **options)
  end

  def error_of
    yield
    raise "expected an error"
  rescue Relspec::Apt::Repository::Error => e
    e.message
  end

  it "reads the by-hash index the Release file names, and no binary-all" do
    archive
    repository = reader
    expect(repository.index_architectures("trixie", "amd64")).to eq(["amd64"])
    expect(repository.packages("trixie", "amd64").entries.keys.sort).to eq(%w[cmake data-common debhelper])
    expect(@server.requests.grep(/Packages|by-hash/))
      .to eq(["/dists/trixie/main/binary-amd64/by-hash/SHA256/#{by_hash_digest('Packages.xz', 'Packages.gz', 'Packages')}"])

    source = Relspec::Availability::AptSource.new(reader, ["main"])
    trixie = Relspec::Plan::Target.parse("trixie/amd64")
    expect(source.lookup_many({ trixie => %w[cmake data-common debhelper-compat stale-only] }))
      .to eq(trixie => [{ "cmake" => true, "data-common" => true, "debhelper-compat" => true, "stale-only" => false }, nil])
    expect(@server.requests.grep(/binary-all/)).to eq([])
  end

  it "reads binary-all too where the Release file does not say No-Support-for-Architecture-all (then a stale one is refused)" do
    archive(no_all: false)
    expect(reader.index_architectures("trixie", "amd64")).to eq(%w[amd64 all])
    expect(error_of { reader.packages("trixie", "all") }).to include("binary-all/by-hash/SHA256/")
  end

  it "falls back to the canonical name when the mirror has no by-hash file, and says a stale one is a sync in progress" do
    archive(by_hash: false)
    message = error_of { reader.packages("trixie", "amd64") }
    expect(message).to eq("#{@server.url}/dists/trixie/main/binary-amd64/Packages.gz does not match the SHA256 of the " \
                          "Release file (got #{File.size(canonical('Packages.gz'))} bytes, expected " \
                          "#{listed_size('Packages.gz')}), also when read again: the archive may be in the middle of " \
                          "an update (mirror sync in progress?); try again later, or use another mirror")
    # by hash, then by name; and once more: one bounded retry
    expect(@server.requests.grep(/binary-amd64/)).to eq([
      "/dists/trixie/main/binary-amd64/by-hash/SHA256/#{listed_sha('Packages.gz')}",
      "/dists/trixie/main/binary-amd64/Packages.gz"
    ] * 2)
  end

  def release_text
    File.read(File.join(@dir, "debian", "dists", "trixie", "Release"))
  end

  # [SHA256, size] the Release file lists for binary-amd64/<name>, or nil.
  def listed(name)
    match = release_text.match(%r{^ (\h{64}) +(\d+) main/binary-amd64/#{Regexp.escape(name)}$})
    match && [match[1], Integer(match[2])]
  end

  def listed_sha(name)
    listed(name).first
  end

  def listed_size(name)
    listed(name).last
  end

  def canonical(name)
    File.join(@dir, "debian", "dists", "trixie", "main", "binary-amd64", name)
  end

  # The digest of the first form the Release file lists.
  def by_hash_digest(*names)
    names.filter_map { |name| listed(name)&.first }.first
  end
end
