# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/worker_pool"

RSpec.describe Relspec::WorkerPool do
  it "works on every item once and returns the items" do
    seen = Queue.new
    items = (1..50).to_a
    expect(described_class.new(4).each(items) { |item| seen << item }).to equal(items)
    expect(Array.new(seen.size) { seen.pop }.sort).to eq(items)
  end

  it "runs at most its size of items at the same time, and uses that many" do
    running = 0
    most = 0
    lock = Mutex.new
    described_class.new(3).each((1..12).to_a) do
      lock.synchronize { most = [most, running += 1].max }
      sleep 0.02
      lock.synchronize { running -= 1 }
    end
    expect(most).to eq(3)
  end

  it "starts no more threads than there are items, and at least one" do
    threads = Queue.new
    described_class.new(8).each(%w[a b]) { threads << Thread.current }
    expect(Array.new(threads.size) { threads.pop }.uniq.size).to be <= 2
    expect(described_class.new(0).size).to eq(1)
    expect(described_class.new(nil).size).to eq(1)
  end

  it "finishes every item when one fails, then raises the failure in the caller" do
    done = Queue.new
    expect do
      described_class.new(2).each((1..10).to_a) do |item|
        raise ArgumentError, "item #{item}" if item == 3

        done << item
      end
    end.to raise_error(ArgumentError, "item 3")
    expect(done.size).to eq(9)
  end

  it "does nothing for no items" do
    called = false
    expect(described_class.new(4).each([]) { called = true }).to eq([])
    expect(called).to be(false)
  end
end
