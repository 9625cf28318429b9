# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/http/client"
require "socket"

# A real server on 127.0.0.1, written inline: one thread, no child process.
RSpec.describe Relspec::Http::Client do
  # Answers each connection with +answer+ after recording the request's head.
  def serve(answer)
    server = TCPServer.new("127.0.0.1", 0)
    heads = Queue.new
    thread = Thread.new do
      loop do
        client = server.accept
        head = +""
        while (line = client.gets) && line != "\r\n"
          head << line
        end
        heads << head
        client.write(answer)
        client.close
      end
    rescue IOError
      nil
    end
    yield URI("http://127.0.0.1:#{server.addr[1]}/dists/x/Release"), heads
  ensure
    server&.close
    thread&.kill
  end

  it "sends the headers, yields the answer and returns the block's value" do
    serve("HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nhello") do |uri, heads|
      body = described_class.new(timeout: 5).get(uri, "Accept" => "application/json", &:read_body)
      expect(body).to eq("hello")
      head = heads.pop
      expect(head).to start_with("GET /dists/x/Release HTTP/1.1\r\n")
      expect(head).to include("Accept: application/json\r\n")
    end
  end

  it "makes exactly one request per call: Net::HTTP's silent resend is off" do
    serve("") do |uri, heads|
      expect { described_class.new(timeout: 5).get(uri) { |response| response } }.to raise_error(EOFError)
      sleep 0.1
      expect(heads.size).to eq(1)
    end
  end

  it "leaves an endless body unread when the block does not read it" do
    serve("HTTP/1.1 404 Not Found\r\nContent-Length: 1000000000\r\n\r\n#{'x' * 1000}") do |uri, _heads|
      started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
      expect(described_class.new(timeout: 5).get(uri, &:code)).to eq("404")
      expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 4
    end
  end

  it "bounds the wait for a silent server by the timeout" do
    serve_silently = TCPServer.new("127.0.0.1", 0)
    uri = URI("http://127.0.0.1:#{serve_silently.addr[1]}/")
    expect { described_class.new(timeout: 0.2).get(uri) { |response| response } }.to raise_error(Net::ReadTimeout)
  ensure
    serve_silently&.close
  end
end
