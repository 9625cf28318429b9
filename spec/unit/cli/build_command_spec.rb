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
end
