# frozen_string_literal: true

require "spec_helper"
require "relspec/builder/scheduler"

# The scheduler's rules on plain entries (it knows nothing of Debian; the
# block is the build). Real builds go through it in scheduler_spec.rb.
RSpec.describe Relspec::Builder::Scheduler do
  SCHEDULER_ENTRY = Struct.new(:source, :build_depends)

  def entries(graph)
    graph.map { |source, deps| SCHEDULER_ENTRY.new(source, deps) }
  end

  it "never runs more than --jobs builds at once, and uses them" do
    running = 0
    peak = 0
    lock = Mutex.new
    outcomes = described_class.new(entries("a" => [], "b" => [], "c" => [], "d" => []), jobs: 2).run do
      lock.synchronize { peak = [peak, running += 1].max }
      sleep 0.3
      lock.synchronize { running -= 1 }
      :files
    end
    expect(outcomes.map(&:status)).to eq(%i[built built built built])
    expect(peak).to eq(2)
  end

  # The early cutoff's keep (docs/abi.md): a success of another name.
  it "reports a Done status as the block gives it, and goes on with its dependents as after a build" do
    outcomes = described_class.new(entries("kept" => [], "user" => ["kept"]), jobs: 1).run do |entry|
      entry.source == "kept" ? described_class::Done.new(status: :kept, value: []) : :files
    end
    expect(outcomes.map { |outcome| [outcome.entry.source, outcome.status, outcome.value] })
      .to eq([["kept", :kept, []], ["user", :built, :files]])
  end

  it "without --keep-going starts nothing after a failure and says so" do
    graph = { "bad" => [], "later" => [], "user" => ["bad"] }
    started = []
    outcomes = described_class.new(entries(graph), jobs: 1).run do |entry|
      started << entry.source
      raise Relspec::BuildError, "bad: dpkg-buildpackage failed" if entry.source == "bad"
    end
    expect(started).to eq(["bad"])
    expect(outcomes.to_h { |outcome| [outcome.entry.source, [outcome.status, outcome.reason]] }).to eq(
      "bad" => [:failed, "bad: dpkg-buildpackage failed"],
      "user" => [:skipped, "build-dependency bad failed"],
      "later" => [:skipped, "not started: the run stopped after bad failed (--keep-going builds the rest)"]
    )
  end

  it "skips what an earlier run built and still builds a dependency cycle" do
    started = []
    described_class.new(entries("done" => [], "x" => %w[y done], "y" => ["x"]), jobs: 2, done: ["done"]).run do |entry|
      started << entry.source
    end
    expect(started).to eq(%w[x y])
  end

  it "waits for the whole build-dependency closure, not only the direct build-dependencies" do
    # b was built by an earlier run; a (b's build-dependency) is built again:
    # c, which uses b and so a, waits for a and is skipped when a fails
    events = []
    lock = Mutex.new
    graph = { "a" => [], "b" => ["a"], "c" => ["b"], "free" => [] }
    described_class.new(entries(graph), jobs: 2, done: ["b"]).run do |entry|
      lock.synchronize { events << [:start, entry.source] }
      sleep 0.2
      lock.synchronize { events << [:finish, entry.source] }
    end
    expect(events.index([:start, "c"])).to be > events.index([:finish, "a"])
    outcomes = described_class.new(entries(graph), jobs: 2, keep_going: true, done: ["b"]).run do |entry|
      raise Relspec::BuildError, "a: failed" if entry.source == "a"
    end
    expect(outcomes.to_h { |outcome| [outcome.entry.source, [outcome.status, outcome.reason]] }).to eq(
      "a" => [:failed, "a: failed"], "c" => [:skipped, "build-dependency a failed"], "free" => [:built, nil]
    )
  end

  it "raises a bug in a build in the calling thread" do
    expect { described_class.new(entries("a" => []), jobs: 1).run { raise ArgumentError, "bug" } }
      .to raise_error(ArgumentError, "bug")
  end
end
