# frozen_string_literal: true

require_relative "../unit_helper"
require "zlib"
require "relspec/osdeps/index_sources"
require_relative "../../support/http_server"

# The Packages indices select reads: files, or repository URLs read with
# --timeout (a real server on 127.0.0.1, a thread).
RSpec.describe Relspec::Osdeps::IndexSources do
  it "reads plain and gzip Packages files" do
    Dir.mktmpdir do |dir|
      text = "Package: rock-a\nVersion: 1\nArchitecture: amd64\n"
      File.write(File.join(dir, "Packages"), text)
      Zlib::GzipWriter.open(File.join(dir, "Packages.gz")) { |gz| gz.write(text) }
      indices = described_class.load([File.join(dir, "Packages"), File.join(dir, "Packages.gz")],
                                     codename: "bookworm", arch: "amd64", trusted: true, keyring: nil)
      expect(indices.map { |index| index.entries.keys }).to eq([["rock-a"], ["rock-a"]])
    end
  end

  it "reads a repository URL with the timeout it is given, naming the source it cannot read" do
    Dir.mktmpdir do |dir|
      server = HttpServer.new(dir)
      server.fail(%r{/InRelease\z}, :stall, seconds: 1)
      expect { described_class.load(["#{server.url}/repo"], codename: "bookworm", arch: "amd64", trusted: true, keyring: nil, timeout: 0.3) }
        .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to include("cannot read the index #{server.url}/repo: ", "no answer within 0.3 s per read") }
    ensure
      server&.stop
    end
  end
end
