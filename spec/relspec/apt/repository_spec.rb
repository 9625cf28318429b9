# frozen_string_literal: true

require "spec_helper"
require "zlib"
require "relspec/apt/repository"
require_relative "../../support/signing_key"

# Reads real reprepro repositories, from disk and over HTTP.
RSpec.describe Relspec::Apt::Repository do
  around do |example|
    Dir.mktmpdir("relspec-apt") do |dir|
      @dir = dir
      example.run
    ensure
      @server&.stop
      # gpg-agent removes its sockets as it exits, racing the folder's removal
      @key&.stop
    end
  end

  def build_repository(**options)
    path = File.join(@dir, "repo")
    builder = AptRepositoryBuilder.new(path, codenames: %w[bionic buster], architectures: %w[amd64 arm64], **options)
    builder.add("rock-x-base-types", "1.0.20200601.103000-1~bionic", codename: "bionic", arch: "amd64",
                                                                     depends: "rock-x-base-cmake (>= 1.0)", source: "rock-x-base-types")
    builder.add("rock-x-base-cmake", "1.0.20200504.080000-1~bionic", codename: "bionic", arch: "amd64", provides: "rock-cmake")
    builder.add("rock-x-data", "3.0-1~buster", codename: "buster", arch: "all")
    path
  end

  def reader(location, **options)
    described_class.new(Relspec::Apt::Fetcher.new(location, timeout: options.delete(:timeout) || 5), **options)
  end

  def serve(path)
    @server = HttpServer.new(path)
  end

  def error_of
    yield
    raise "expected an error"
  rescue described_class::Error => e
    e.message
  end

  it "reads the packages of each codename and architecture from disk" do
    repository = reader(build_repository, trusted: true)
    index = repository.packages("bionic", "amd64")
    expect(index.entries.keys.sort).to eq(%w[rock-x-base-cmake rock-x-base-types])
    expect(index["rock-x-base-types"].to_h).to include(version: "1.0.20200601.103000-1~bionic",
                                                       depends: "rock-x-base-cmake (>= 1.0)", source: "rock-x-base-types")
    expect(index["rock-x-base-cmake"].provides).to eq("rock-cmake")
    expect(repository.packages("buster", "arm64").entries.keys).to eq(["rock-x-data"])
    expect(repository.release("bionic").sha256)
      .to eq(Digest::SHA256.file(File.join(@dir, "repo", "dists", "bionic", "Release")).hexdigest)
  end

  it "reads the same over HTTP, and only the Release file once the indices are cached" do
    path = build_repository
    serve(path)
    cache = Relspec::Apt::Cache.new(File.join(@dir, "cache"))
    first = reader(@server.url, trusted: true, cache: cache).packages("bionic", "amd64")
    expect(first.entries).to eq(reader(path, trusted: true).packages("bionic", "amd64").entries)
    fetched_before = @server.requests.dup
    reader(@server.url, trusted: true, cache: cache).packages("bionic", "amd64")
    second = @server.requests.drop(fetched_before.size)
    expect(fetched_before.grep(/Packages/)).not_to be_empty
    expect(second.grep(/Packages/)).to be_empty
    expect(second).to include("/dists/bionic/Release")
  end

  # A gpg key of the test's own: [gnupg home, exported keyring].
  def signing_key
    home = File.join(@dir, "gnupg")
    Dir.mkdir(home, 0o700)
    @key = SigningKey.new(home)
    keyring = File.join(@dir, "keyring.gpg")
    File.binwrite(keyring, @key.public_keyring)
    [home, keyring]
  end

  it "refuses a signed Release of another distribution served under this one's name (a replay)" do
    home, keyring = signing_key
    path = build_repository(sign_with: "yes", gnupg_home: home)
    FileUtils.cp(File.join(path, "dists", "buster", "InRelease"), File.join(path, "dists", "bionic", "InRelease"))
    expect(error_of { reader(path, keyring: keyring).packages("bionic", "amd64") })
      .to match(%r{dists/bionic: the Release file is of buster, not bionic})
  end

  it "refuses a signed Release whose Valid-Until has passed" do
    home, keyring = signing_key
    path = build_repository(sign_with: "yes", gnupg_home: home, valid_for: "1d")
    expect(reader(path, keyring: keyring).release("bionic").valid_until).to be > Time.now
    later = -> { Time.now + (3 * 86_400) }
    expect(error_of { reader(path, keyring: keyring, clock: later).release("bionic") })
      .to match(%r{dists/bionic: the Release file expired on \d{4}-\d\d-\d\d .* \(Valid-Until\)})
  end

  it "reads every member of a Packages.gz made of several gzip members" do
    path = build_repository
    ReleaseFileEditor.keep_only(path, "bionic", "main/binary-amd64", "main/binary-amd64/Packages.gz")
    two = Zlib.gzip("Package: first\nVersion: 1.0\n\n") + Zlib.gzip("Package: second\nVersion: 2.0\n")
    ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages.gz", two)
    expect(reader(path, trusted: true).packages("bionic", "amd64").entries.keys).to eq(%w[first second])
  end

  it "refuses an index Version that is not a Debian version, naming the stanza" do
    path = build_repository
    ReleaseFileEditor.keep_only(path, "bionic", "main/binary-amd64", "main/binary-amd64/Packages")
    ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages",
                                    "Package: a\nVersion: 1.0\n\nPackage: b\nVersion: 1.0) evil\n")
    expect(error_of { reader(path, trusted: true).packages("bionic", "amd64") })
      .to match(%r{binary-amd64/Packages: malformed index: stanza 2 \(Package: b\) has an invalid Version "1.0\) evil"})
  end

  it "verifies InRelease with a keyring, and refuses a bad signature or a foreign key" do
    home, keyring = signing_key
    path = build_repository(sign_with: "yes", gnupg_home: home)
    expect(reader(path, keyring: keyring).packages("bionic", "amd64").size).to eq(2)

    in_release = File.join(path, "dists", "bionic", "InRelease")
    File.write(in_release, File.read(in_release).sub("Codename: bionic", "Codename: bionix"))
    expect(error_of { reader(path, keyring: keyring).release("bionic") }).to match(/InRelease: signature check failed: BAD signature/)
    expect(error_of { reader(path, keyring: File.join(CliRunner::ROOT, "Gemfile")).release("buster") })
      .to match(/signature check failed/)
    expect(error_of { reader(path).release("buster") }).to match(/no keyring given \(set keyring:, or trusted: true\)/)
  end

  it "refuses an unsigned repository unless it is trusted" do
    expect(error_of { reader(build_repository).release("bionic") })
      .to match(%r{repo/dists/bionic/Release is unsigned: set keyring:, or trusted: true})
  end

  it "refuses an index whose SHA256 does not match the Release file" do
    path = build_repository
    File.binwrite(File.join(path, "dists", "bionic", "main", "binary-amd64", "Packages.gz"), Zlib.gzip("Package: evil\n"))
    expect(error_of { reader(path, trusted: true).packages("bionic", "amd64") })
      .to match(%r{repo/dists/bionic/main/binary-amd64/Packages.gz does not match the SHA256 of the Release file})
  end

  it "reads the next index the Release file lists when the first is missing, as on mirrors that drop Packages.xz" do
    path = build_repository
    index = File.join(path, "dists", "bionic", "main", "binary-amd64")
    # reprepro lists Packages.gz and Packages; the compressed one goes away
    expect(File.read(File.join(path, "dists", "bionic", "Release"))).to include("main/binary-amd64/Packages.gz")
    File.delete(File.join(index, "Packages.gz"))
    expect(reader(path, trusted: true).packages("bionic", "amd64").entries.keys).to include("rock-x-base-types")
    File.delete(File.join(index, "Packages"))
    expect(error_of { reader(path, trusted: true).packages("bionic", "amd64") })
      .to match(%r{binary-amd64/Packages.gz is listed in the Release file but missing})
  end

  it "refuses a truncated .gz index" do
    path = build_repository
    gz = File.binread(File.join(path, "dists", "bionic", "main", "binary-amd64", "Packages.gz"))
    ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages.gz", gz[0, gz.size / 2])
    expect(error_of { reader(path, trusted: true).packages("bionic", "amd64") })
      .to match(%r{binary-amd64/Packages.gz: corrupt gzip data})
  end

  it "refuses a malformed stanza with its line" do
    path = build_repository
    ReleaseFileEditor.keep_only(path, "bionic", "main/binary-amd64", "main/binary-amd64/Packages")
    ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages", "Package: a\nVersion: 1\n\nnot a field\nVersion: 2\n")
    expect(error_of { reader(path, trusted: true).packages("bionic", "amd64") })
      .to match(%r{binary-amd64/Packages: malformed index: line 4: expected "Field: value"})
  end

  it "says which codename is missing" do
    expect(error_of { reader(build_repository, trusted: true).release("focal") })
      .to match(%r{repo has no distribution focal \(no dists/focal/InRelease or Release\)})
  end

  it "treats HTTP 404 as missing and gives up on HTTP 500 after bounded retries" do
    serve(build_repository)
    @server.fail(%r{/dists/bionic/}, 404)
    expect(error_of { reader(@server.url, trusted: true).release("bionic") }).to include("#{@server.url} has no distribution bionic")
    @server.fail(%r{/dists/buster/}, 500)
    message = error_of { reader(@server.url, trusted: true).release("buster") }
    expect(message).to match(%r{\A#{@server.url}/dists/buster/InRelease: HTTP 500 Internal Server Error \(after 3 attempts, \d+\.\d s in all\)\z})
    expect(@server.requests.count("/dists/buster/InRelease")).to eq(3)
  end

  it "follows redirects, a bounded number of times" do
    serve(build_repository)
    @server.fail(%r{\A/dists/bionic/}, :redirect)
    expect(reader(@server.url, trusted: true).packages("bionic", "amd64")).not_to be_nil
    expect(@server.requests).to include("/dists/bionic/InRelease", "/moved/dists/bionic/InRelease")
    @server.fail(%r{\A(/moved)*/dists/buster/}, :redirect)
    expect(error_of { reader(@server.url, trusted: true).release("buster") })
      .to match(%r{/moved/moved/moved/dists/buster/InRelease: HTTP 302 redirect to ".*/moved/moved/moved/moved/dists/buster/InRelease" not followed})
  end

  it "gives up on a server that stalls, after the timeout" do
    serve(build_repository)
    @server.fail(%r{/dists/bionic/InRelease}, :stall, seconds: 3)
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    message = error_of { described_class.new(Relspec::Apt::Fetcher.new(@server.url, timeout: 0.3, retries: 2), trusted: true).release("bionic") }
    expect(message).to match(%r{\A#{@server.url}/dists/bionic/InRelease: no answer within 0.3 s per read \(after 2 attempts, 0\.\d s in all\)\z})
    # each attempt is one request (Net::HTTP's own silent retry is off)
    expect(@server.requests.count("/dists/bionic/InRelease")).to eq(2)
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 3
  end
end
