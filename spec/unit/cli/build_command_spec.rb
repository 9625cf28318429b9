# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/cli/build_command"
require "relspec/cli/build_progress"
require "relspec/cli/build_progress_lines"

# Which progress `relspec build` shows, by where its streams go.
RSpec.describe Relspec::CLI::BuildCommand do
  def stream(tty)
    StringIO.new.tap { |io| io.define_singleton_method(:tty?) { tty } }
  end

  def listener(stdout_tty:, stderr_tty:, format: "text", quiet: false)
    command = described_class.new(path: "s.yml", out: "build", backend: "host", jobs: 1, targets: nil, keep_going: false,
                                  rebuild: false, prepare: false, format: format, out_io: stream(stdout_tty),
                                  progress_io: quiet ? nil : stream(stderr_tty))
    command.send(:listener)
  end

  it "shows the bar on a terminal, lines on a stdout that is not one, both when only stdout goes to a file" do
    expect(listener(stdout_tty: true, stderr_tty: true)).to be_a(Relspec::CLI::BuildProgress)
    expect(listener(stdout_tty: false, stderr_tty: false)).to be_a(Relspec::CLI::BuildProgressLines)
    both = listener(stdout_tty: false, stderr_tty: true) # bin/demo > log
    expect(both.all.map(&:class)).to eq([Relspec::CLI::BuildProgress, Relspec::CLI::BuildProgressLines])
    expect(listener(stdout_tty: true, stderr_tty: false)).to be_nil
  end

  it "shows nothing with --quiet or --format json" do
    expect(listener(stdout_tty: false, stderr_tty: true, quiet: true)).to be_nil
    expect(listener(stdout_tty: false, stderr_tty: true, format: "json")).to be_nil
  end

  it "hands every event to each listener" do
    seen = []
    recorder = Object.new
    %i[start building finished].each { |event| recorder.define_singleton_method(event) { |*args| seen << [event, *args] } }
    both = described_class::Listeners.new([recorder, recorder])
    both.start("t", 2, 0)
    both.building(:entry)
    both.finished(:outcome)
    expect(seen).to eq(([[:start, "t", 2, 0]] * 2) + ([%i[building entry]] * 2) + ([%i[finished outcome]] * 2))
  end

  it "shows each rebuilt package's interface verdict in its row, with the first change" do
    results = Relspec::Builder::BuildResults
    interface = ->(verdict, changes) { results::Interface.new(against: "1-1", verdict: verdict, compared: 3, changes: changes) }
    records = [results::Record.new(source: "rock-a", version: "1-2", status: "built", duration: 2.0, files: [],
                                   interface: interface.call("unchanged", [])),
               results::Record.new(source: "rock-bb", version: "1-2", status: "built", duration: 3.0, files: [],
                                   interface: interface.call("changed", ["opt/r/include/b.h: differs", "x: added"])),
               results::Record.new(source: "rock-c", version: "1-1", status: "built", duration: 1.0, files: []),
               results::Record.new(source: "rock-e", version: "1-3", status: "built", duration: 1.0, files: [],
                                   interface: interface.call("unchanged", []).to_h.transform_keys(&:to_sym)
                                                       .then { |fields| results::Interface.new(**fields, held: "1-0") }),
               results::Record.new(source: "rock-d", version: "1-2", status: "built", duration: 1.0, files: [],
                                   interface: interface.call("unchanged", []),
                                   cutoff: results::Cutoff.new(keeps: "1-1", verdict: "keep",
                                                               reason: "the interface of rock-a did not change"))]
    report = Relspec::Builder::TargetReport.new(target: "bookworm/amd64", dir: "out/r/bookworm-amd64",
                                                results: Struct.new(:entries).new(records), outcomes: [], reused: 0)
    io = StringIO.new
    command = described_class.new(path: "s.yml", out: "build", backend: "host", jobs: 1, targets: nil, keep_going: false,
                                  rebuild: false, prepare: false, format: "text", out_io: io, progress_io: nil)
    command.send(:print_table, report)
    expect(io.string.lines.drop(1)).to eq(["  rock-a   1-2  built  2.0 s  interface unchanged from 1-1\n",
                                           "  rock-bb  1-2  built  3.0 s  interface changed from 1-1: opt/r/include/b.h: differs\n",
                                           "  rock-c   1-1  built  1.0 s\n",
                                           "  rock-e   1-3  built  1.0 s  interface unchanged from 1-1 " \
                                           "(unpublished: the repository holds 1-0)\n",
                                           "  rock-d   1-2  built  1.0 s  early cutoff: keeps 1-1: the interface of rock-a did not change\n"])
  end
end
