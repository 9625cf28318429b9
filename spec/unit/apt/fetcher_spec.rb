# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/fetcher"
require_relative "../../support/http_server"

# A repository's files from a folder or over http(s) (Http::Download): a
# missing file is nil, anything else that cannot be read one Failure.
RSpec.describe Relspec::Apt::Fetcher, :tmpdir do
  before do
    FileUtils.mkdir_p(File.join(@dir, "dists"))
    File.write(File.join(@dir, "dists", "Release"), "Origin: x\n")
  end

  it "reads a folder's regular files, a missing one as nil, and refuses others and oversized ones" do
    fetcher = described_class.new("file://#{@dir}/")
    expect([fetcher.remote?, fetcher.fetch("dists/Release"), fetcher.fetch("dists/none")]).to eq([false, "Origin: x\n", nil])
    expect { fetcher.fetch("dists") }.to raise_error(described_class::Failure, /not a regular file \(directory\)/)
    expect { fetcher.fetch("dists/Release", max_bytes: 3) }.to raise_error(described_class::Failure, /larger than 3 bytes/)
  end

  it "reads over http, following a redirect; 404 is nil, a refusal and a server past its retries a Failure" do
    server = HttpServer.new(@dir)
    fetcher = described_class.new(server.url, timeout: 1)
    server.fail(%r{\A/dists/Release\z}, :redirect)
    server.fail(%r{\A/broken\z}, 500)
    server.fail(%r{\A/gone\z}, 404)
    expect([fetcher.remote?, fetcher.fetch("dists/Release"), fetcher.fetch("gone")]).to eq([true, "Origin: x\n", nil])
    expect { fetcher.fetch("dists/Release", max_bytes: 3) }
      .to raise_error(described_class::Failure, %r{/moved/dists/Release: the server sends more than 3 bytes})
    expect { fetcher.fetch("broken") }.to raise_error(described_class::Failure, %r{\A#{server.url}/broken: HTTP 500 .*after 3 attempts})
  ensure
    server&.stop
  end
end
