# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/catalog/package"
require "relspec/catalog/archive_import"
require_relative "../../support/http_server"

RSpec.describe Relspec::Catalog::ArchiveImport, :tmpdir do
  def package(url)
    Relspec::Catalog::Package.new(name: "external/x", package_set: "set", build_type: "archive", commit_time: nil,
                                  source_dir: "src/external/x", vcs: Relspec::Catalog::Vcs.new(type: "archive", url: url).freeze)
  end

  def import
    described_class.new(cache: File.join(@dir, "cache"), timeout: 1)
  end

  def archive(content, time)
    path = File.join(@dir, "x-1.0.tar.gz")
    File.binwrite(path, content)
    File.utime(time, time, path)
    path
  end

  it "versions a local archive by its modification time and records its checksum, once in the cache" do
    path = archive("bytes", Time.utc(2021, 1, 2, 3, 4, 5))
    resolved = import.resolve(package("file://#{path}"))
    expect(resolved.commit_time).to eq("2021-01-02T03:04:05Z")
    expect(resolved.vcs.sha256).to eq(Digest::SHA256.hexdigest("bytes"))
    expect(File.binread(import.path_of(resolved))).to eq("bytes")
    # fetched once: a changed file is not seen until the cache entry goes
    archive("other", Time.utc(2022, 1, 1))
    expect(import.resolve(package("file://#{path}")).vcs.sha256).to eq(resolved.vcs.sha256)
  end

  it "refuses a cached archive that is not the one planned" do
    path = archive("bytes", Time.utc(2021, 1, 2))
    resolved = import.resolve(package("file://#{path}"))
    File.binwrite(import.path_of(resolved), "tampered")
    expect { import.path_of(resolved) }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to include("is not the one planned") }
  end

  it "refuses urls it cannot fetch, naming the package" do
    ["ftp://example.org/x.tar.gz", "file://#{@dir}/missing.tar.gz", "::"].each do |url|
      expect { import.resolve(package(url)) }.to raise_error(Relspec::InvalidInput) do |e|
        expect(e.diagnostics.first.rule).to eq("archive-import")
        expect(e.diagnostics.first.message).to start_with("external/x: ")
      end
    end
  end

  # a real server on 127.0.0.1 (a thread): an answer that may pass is asked
  # again (Http::Download), as every download of relspec
  it "asks again after a 503 and gets the archive" do
    served = File.join(@dir, "served")
    FileUtils.mkdir_p(served)
    File.binwrite(File.join(served, "x-1.0.tar.gz"), "bytes")
    File.utime(Time.utc(2021), Time.utc(2021), File.join(served, "x-1.0.tar.gz"))
    server = HttpServer.new(served)
    server.fail(%r{\A/x}, :unavailable_once)
    resolved = import.resolve(package("#{server.url}/x-1.0.tar.gz"))
    expect(server.requests).to eq(["/x-1.0.tar.gz"] * 2)
    expect([resolved.vcs.sha256, resolved.commit_time]).to eq([Digest::SHA256.hexdigest("bytes"), "2021-01-01T00:00:00Z"])
  ensure
    server&.stop
  end

  # a real server on 127.0.0.1 (a thread): a redirect, then no Last-Modified
  it "follows a redirect and, without Last-Modified, takes the newest time of the archive's files" do
    served = File.join(@dir, "served", "redir")
    FileUtils.mkdir_p(served)
    # the archive's one file dated 2005-06-07 in its tar header (TarWriter
    # would date it by RubyGems' source date, fixed at its first use in the
    # process, not when the test runs)
    header = Gem::Package::TarHeader.new(name: "x-1.0/README", mode: 0o644, size: 2, prefix: "",
                                         mtime: Time.utc(2005, 6, 7, 8, 9, 10).to_i)
    tar = "#{header}#{"x\n".ljust(512, "\0")}#{"\0" * 1024}"
    tarball = StringIO.new
    Zlib::GzipWriter.wrap(tarball) { |gzip| gzip.write(tar) }
    File.binwrite(File.join(served, "x-1.0.tar.gz"), tarball.string)
    # what a Last-Modified would say, were it sent
    File.utime(Time.utc(2001), Time.utc(2001), File.join(served, "x-1.0.tar.gz"))
    server = HttpServer.new(File.dirname(served))
    server.fail(%r{\A/redir/}, :redirect)
    server.fail(%r{\A/moved/}, :no_last_modified)
    resolved = import.resolve(package("#{server.url}/redir/x-1.0.tar.gz"))
    expect(server.requests).to eq(["/redir/x-1.0.tar.gz", "/moved/redir/x-1.0.tar.gz"])
    expect(resolved.vcs.sha256).to eq(Digest::SHA256.hexdigest(tarball.string))
    # the time comes from the archive's files, not from the server's file (2001)
    expect(Time.parse(resolved.commit_time)).to eq(Time.utc(2005, 6, 7, 8, 9, 10))
  ensure
    server&.stop
  end
end
