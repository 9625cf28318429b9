# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/cli/build_progress_lines"

RSpec.describe Relspec::CLI::BuildProgressLines do
  # Builder's plan entry and scheduler outcome, as far as the lines read them.
  let(:entry_type) { Struct.new(:source) }
  let(:outcome_type) { Struct.new(:entry, :status, :reason, :duration, keyword_init: true) }

  def entry(source)
    entry_type.new(source)
  end

  def outcome(source, status, reason: nil, duration: nil)
    outcome_type.new(entry: entry(source), status: status, reason: reason, duration: duration)
  end

  let(:io) { StringIO.new }
  let(:lines) { described_class.new(io) }

  it "says a line when a package starts and when it ends, with done/total, status and time" do
    lines.start("bookworm/amd64", 3, 1)
    lines.building(entry("rock-a"))
    lines.finished(outcome("rock-a", :failed, reason: "cmake failed", duration: 2.25))
    lines.finished(outcome("rock-b", :skipped, reason: "build-dependency rock-a failed\nmore"))
    expect(io.string).to eq(<<~TEXT)
      bookworm/amd64: 3 packages, 1 already built
      bookworm/amd64 [1/3] started rock-a
      bookworm/amd64 [2/3] failed rock-a in 2.2 s
      bookworm/amd64 [3/3] skipped rock-b: build-dependency rock-a failed
    TEXT
  end

  it "says nothing for a target that builds nothing, and announces each target once" do
    lines.start("bookworm/amd64", 0, 0)
    lines.start("bookworm/arm64", 1, 0)
    lines.building(entry("rock-a"))
    lines.finished(outcome("rock-a", :built, duration: 10))
    expect(io.string).to eq(<<~TEXT)
      bookworm/arm64: 1 package, 0 already built
      bookworm/arm64 [0/1] started rock-a
      bookworm/arm64 [1/1] built rock-a in 10.0 s
    TEXT
  end
end
