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
end
