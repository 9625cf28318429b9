# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/http/download"
require_relative "../../support/http_server"

# relspec's one download (apt indices, gems, archive imports) against a real
# server on 127.0.0.1 (a thread): redirects, retries, the timeout.
RSpec.describe Relspec::Http::Download, :tmpdir do
  around do |example|
    File.write(File.join(@dir, "file"), "bytes")
    @server = HttpServer.new(@dir)
    example.run
  ensure
    @server&.stop
  end

  let(:pauses) { [] }
  let(:download) { described_class.new(timeout: 1, sleeper: ->(seconds) { pauses << seconds }) }

  def body(path)
    download.get(URI("#{@server.url}#{path}")) { |uri, response| [uri.path, response.code, response.body] }
  end

  it "follows a redirect and gives the block the final answer and where it came from" do
    @server.fail(%r{\A/file\z}, :redirect)
    expect(body("/file")).to eq(["/moved/file", "200", "bytes"])
  end

  it "asks again after a 5xx, pausing, and gives other answers to the block" do
    @server.fail(%r{\A/file\z}, :unavailable_once)
    expect(body("/file")).to eq(["/file", "200", "bytes"])
    expect(pauses).to eq([described_class::BACKOFF])
    expect(body("/none")).to eq(["/none", "404", nil]).or eq(["/none", "404", ""])
  end

  it "gives up after its attempts, saying how many and why" do
    @server.fail(%r{\A/file\z}, 500)
    expect { body("/file") }.to raise_error(described_class::Failed, %r{/file: HTTP 500 .* \(after 3 attempts, [\d.]+ s in all\)\z})
    expect(@server.requests).to eq(["/file"] * 3)
  end

  it "waits the timeout for each answer, not more" do
    @server.fail(%r{\A/file\z}, :stall, seconds: 1)
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    expect { described_class.new(timeout: 0.5, retries: 1).get(URI("#{@server.url}/file")) { :never } }
      .to raise_error(described_class::Failed, %r{/file: no answer within 0\.5 s per read \(after 1 attempt,})
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 2
  end

  it "refuses a redirect past the third" do
    @server.fail(%r{\A/(moved/)*file\z}, :redirect)
    expect { body("/file") }.to raise_error(described_class::Failed, %r{/moved/moved/moved/file: HTTP 302 redirect to ".*" not followed\z})
  end

  it "lets the block's own errors through, untried again" do
    expect { download.get(URI("#{@server.url}/file")) { raise ArgumentError, "mine" } }.to raise_error(ArgumentError, "mine")
    expect(@server.requests).to eq(["/file"])
  end
end
