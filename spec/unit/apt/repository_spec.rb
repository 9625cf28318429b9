# frozen_string_literal: true

require_relative "../unit_helper"
require "digest"
require "zlib"
require "relspec/apt/repository"

# A repository folder written here (no reprepro): what #index_digest names
# is the index #packages reads.
RSpec.describe Relspec::Apt::Repository, :tmpdir do
  def write_repository(gz_text, xz_listed:)
    gz = Zlib.gzip(gz_text)
    FileUtils.mkdir_p(File.join(@dir, "dists", "bookworm", "main", "binary-amd64"))
    File.binwrite(File.join(@dir, "dists", "bookworm", "main", "binary-amd64", "Packages.gz"), gz)
    listed = xz_listed ? " #{'0' * 64} 123 main/binary-amd64/Packages.xz\n" : ""
    File.write(File.join(@dir, "dists", "bookworm", "Release"),
               "Codename: bookworm\nArchitectures: amd64\nComponents: main\nSHA256:\n#{listed} " \
               "#{Digest::SHA256.hexdigest(gz)} #{gz.bytesize} main/binary-amd64/Packages.gz\n")
    Digest::SHA256.hexdigest(gz)
  end

  let(:repository) { described_class.new(Relspec::Apt::Fetcher.new(@dir), trusted: true) }

  it "names the index by what its Release file lists, reading no index, and reads the first listed form present" do
    write_repository("Package: ruby-foo\nVersion: 1.0-1\n", xz_listed: true)
    fetcher = Relspec::Apt::Fetcher.new(@dir)
    asked = []
    fetcher.define_singleton_method(:fetch) do |path, **options|
      asked << path
      super(path, **options)
    end
    digest = described_class.new(fetcher, trusted: true).index_digest("bookworm", "amd64")
    expect(digest).to match(/\A\h{64}\z/)
    expect(asked.grep(/Packages/)).to eq([])
    expect(repository.packages("bookworm", "amd64")["ruby-foo"].version).to eq("1.0-1")
  end

  it "names another digest when only the present form changed (an absent .xz listed first)" do
    write_repository("Package: ruby-foo\nVersion: 1.0-1\n", xz_listed: true)
    before = described_class.new(Relspec::Apt::Fetcher.new(@dir), trusted: true).index_digest("bookworm", "amd64")
    write_repository("Package: ruby-foo\nVersion: 2.0-1\n", xz_listed: true)
    after = described_class.new(Relspec::Apt::Fetcher.new(@dir), trusted: true).index_digest("bookworm", "amd64")
    expect(after).not_to eq(before)
  end

  it "reads any file its Release file lists, checked against it and uncompressed, and refuses the others" do
    write_repository("Package: ruby-foo\nVersion: 1.0-1\n", xz_listed: true)
    expect(repository.listed_text("bookworm", "main/binary-amd64/Packages.gz")).to eq("Package: ruby-foo\nVersion: 1.0-1\n")
    expect { repository.listed_text("bookworm", "main/binary-amd64/Packages.xz") }
      .to raise_error(described_class::Error, %r{dists/bookworm/main/binary-amd64/Packages.xz is listed in the Release file but missing})
    expect { repository.listed_text("bookworm", "main/binary-amd64/Packages") }
      .to raise_error(described_class::Error, %r{dists/bookworm/main/binary-amd64/Packages is not listed in the Release file})
    gz = File.join(@dir, "dists", "bookworm", "main", "binary-amd64", "Packages.gz")
    File.binwrite(gz, Zlib.gzip("Package: ruby-fob\nVersion: 1.0-1\n"))
    expect { described_class.new(Relspec::Apt::Fetcher.new(@dir), trusted: true).listed_text("bookworm", "main/binary-amd64/Packages.gz") }
      .to raise_error(described_class::Error, /Packages.gz does not match the SHA256 of the Release file/)
  end

  # An uncompressed index listed by the Release file, with by-hash on.
  def write_hashed(listed_text, canonical_text, by_hash: true, sha: Digest::SHA256.hexdigest(listed_text))
    folder = File.join(@dir, "dists", "trixie", "main", "binary-amd64")
    FileUtils.mkdir_p(File.join(folder, "by-hash", "SHA256"))
    File.binwrite(File.join(folder, "Packages"), canonical_text)
    File.binwrite(File.join(folder, "by-hash", "SHA256", sha), listed_text) if by_hash && sha.match?(/\A\h{64}\z/)
    File.write(File.join(@dir, "dists", "trixie", "Release"),
               "Codename: trixie\nArchitectures: all amd64\nAcquire-By-Hash: yes\n" \
               "No-Support-for-Architecture-all: Packages\nSHA256:\n #{sha} #{listed_text.bytesize} main/binary-amd64/Packages\n")
  end

  def recording(fetcher, asked)
    fetcher.define_singleton_method(:fetch) do |path, **options|
      asked << path
      super(path, **options)
    end
    fetcher
  end

  let(:new_index) { "Package: cmake\nVersion: 3.31.6-2\n" }
  let(:old_index) { "Package: cmake\nVersion: 3.25.1-1\n" }

  it "reads an index by its hash when the Release file offers that, whatever the canonical file holds" do
    write_hashed(new_index, old_index)
    expect(repository.packages("trixie", "amd64")["cmake"].version).to eq("3.31.6-2")
    expect(repository.index_architectures("trixie", "amd64")).to eq(["amd64"])
  end

  it "reads the canonical file when there is no by-hash file, once more when it does not match, then gives up" do
    write_hashed(new_index, old_index, by_hash: false)
    asked = []
    fetcher = recording(Relspec::Apt::Fetcher.new(@dir), asked)
    expect { described_class.new(fetcher, trusted: true).packages("trixie", "amd64") }
      .to raise_error(described_class::Error, /Packages does not match the SHA256 of the Release file \(got SHA256 \h{64}, expected \h{64}\), also when read again: .*mirror sync in progress/)
    hashed = "dists/trixie/main/binary-amd64/by-hash/SHA256/#{Digest::SHA256.hexdigest(new_index)}"
    expect(asked.grep(/binary/)).to eq([hashed, "dists/trixie/main/binary-amd64/Packages"] * 2)
  end

  it "takes the second reading when the index was replaced in between (a sync that just finished)" do
    write_hashed(new_index, old_index, by_hash: false)
    new_text = new_index
    fetcher = Relspec::Apt::Fetcher.new(@dir)
    fetcher.define_singleton_method(:fetch) do |path, **options|
      bytes = super(path, **options)
      File.binwrite(File.join(base, path), new_text) if path.end_with?("binary-amd64/Packages")
      bytes
    end
    expect(described_class.new(fetcher, trusted: true).packages("trixie", "amd64")["cmake"].version).to eq("3.31.6-2")
  end

  it "refuses a listed SHA256 that is not one before it names a file to fetch" do
    write_hashed(new_index, old_index, sha: "../../../../etc/passwd")
    asked = []
    fetcher = recording(Relspec::Apt::Fetcher.new(@dir), asked)
    expect { described_class.new(fetcher, trusted: true).packages("trixie", "amd64") }
      .to raise_error(described_class::Error, %r{Release: the SHA256 of main/binary-amd64/Packages is not 64 hex digits \(\.\./\.\./\.\./\.\./etc/passwd\): a malformed Release file})
    expect(asked.grep(/binary/)).to eq([])
  end
end
