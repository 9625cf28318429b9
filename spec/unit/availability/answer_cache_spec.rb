# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/availability/answer_cache"

# Launchpad's answers in a temporary folder, on a clock the test moves: fresh
# answers come back, old ones and damaged ones read as unknown, and a folder
# that cannot be written costs the answer only (one note).
RSpec.describe Relspec::Availability::AnswerCache, :tmpdir do
  let(:now) { [1_000_000] }
  let(:notes) { StringIO.new }
  let(:cache) do
    described_class.new(@dir, clock: -> { now.first }, writer: Relspec::CacheWriter.new(notes: notes))
  end

  it "keeps a found name for a day and a missing one for an hour" do
    cache.write("found", true)
    cache.write("missing", false)
    now[0] += 3599
    expect([cache.read("found"), cache.read("missing")]).to eq([true, false])
    now[0] += 1
    expect([cache.read("found"), cache.read("missing")]).to eq([true, nil])
    now[0] += 24 * 3600
    expect(cache.read("found")).to be_nil
  end

  it "reads a damaged answer as unknown" do
    cache.write("key", true)
    File.write(Dir.glob(File.join(@dir, "*", "*")).first, "found soon\n")
    expect(cache.read("key")).to be_nil
  end

  it "goes on with one note when its folder cannot be written" do
    File.write(File.join(@dir, "blocked"), "")
    blocked = described_class.new(File.join(@dir, "blocked"), writer: Relspec::CacheWriter.new(notes: notes))
    blocked.write("a", true)
    blocked.write("b", true)
    expect(blocked.read("a")).to be_nil
    expect(notes.string.lines.size).to eq(1)
    expect(notes.string).to include("cannot be written (File exists); going on without it (only slower)")
  end
end
