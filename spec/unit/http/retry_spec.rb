# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/http/retry"

RSpec.describe Relspec::Http::Retry do
  let(:pauses) { [] }

  def retry_loop(attempts: 3, deadline: 5, max_retry_after: 60, backoff: ->(attempt) { attempt * 0.5 })
    described_class.new(attempts: attempts, deadline: deadline, backoff: backoff, max_retry_after: max_retry_after,
                        sleeper: ->(seconds) { pauses << seconds })
  end

  it "returns the block's value, on the first attempt when it succeeds" do
    seen = []
    expect(retry_loop.run { |attempt| (seen << attempt) && "body" }).to eq("body")
    expect(seen).to eq([1])
    expect(pauses).to eq([])
  end

  it "repeats what may pass, with the backoff between attempts, until it succeeds" do
    answers = [Errno::ECONNREFUSED, Net::ReadTimeout, :ok]
    value = retry_loop.run do |attempt|
      answer = answers[attempt - 1]
      answer == :ok ? "third" : raise(answer)
    end
    expect(value).to eq("third")
    expect(pauses).to eq([0.5, 1.0])
  end

  it "gives up after the attempts, naming the last error and how many were made" do
    expect { retry_loop(attempts: 2).run { raise Errno::ECONNRESET } }.to raise_error(described_class::GaveUp) do |error|
      expect(error.attempts).to eq(2)
      expect(error.last).to be_a(Errno::ECONNRESET)
      expect(error.message).to include("Connection reset")
    end
    expect(pauses.size).to eq(1)
  end

  it "waits as long as Retry-After asks instead of the backoff" do
    calls = 0
    retry_loop.run do
      calls += 1
      raise Relspec::Http::Retryable.new("HTTP 503", 7) if calls == 1

      "ok"
    end
    expect(pauses).to eq([7])
  end

  it "uses the backoff when the answer names no pause" do
    calls = 0
    retry_loop.run { (calls += 1) == 1 ? raise(Relspec::Http::Retryable, "HTTP 500") : "ok" }
    expect(pauses).to eq([0.5])
  end

  it "refuses a Retry-After longer than it may wait, without waiting" do
    expect { retry_loop(max_retry_after: 30).run { raise Relspec::Http::Retryable.new("HTTP 429", 3600) } }
      .to raise_error(described_class::WaitTooLong) { |error| expect(error.seconds).to eq(3600) }
    expect(pauses).to eq([])
  end

  it "stops an attempt at the overall deadline, however the server drips" do
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    expect { retry_loop(deadline: 0.2).run { sleep 5 } }.to raise_error(described_class::DeadlineExceeded) do |error|
      expect(error.attempts).to eq(1)
      expect(error.elapsed).to be >= 0.2
    end
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 2
  end

  it "counts pauses against the deadline: no attempt starts after it" do
    slow = described_class.new(attempts: 5, deadline: 0.1, backoff: ->(_) { 0.2 }, max_retry_after: 60,
                               sleeper: ->(seconds) { sleep(seconds) })
    attempts = 0
    expect { slow.run { (attempts += 1) && raise(Errno::ECONNREFUSED) } }.to raise_error(described_class::DeadlineExceeded)
    expect(attempts).to eq(1)
  end

  it "lets other errors through at once: they are the caller's to word" do
    attempts = 0
    expect { retry_loop.run { (attempts += 1) && raise(ArgumentError, "bad") } }.to raise_error(ArgumentError, "bad")
    expect(attempts).to eq(1)
  end
end
