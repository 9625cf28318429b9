# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/cli/friendly_errors"

RSpec.describe Relspec::CLI::FriendlyErrors do
  let(:stderr) { StringIO.new }

  def run(&block)
    [described_class.wrap(stderr: stderr, debug: false, &block), stderr.string]
  end

  # Issue 46, case 14: a command-line value in the message.
  it "prints a command-line error on one line, its control characters and newlines escaped" do
    expect(run { raise Relspec::InvalidOption, "x\e[31m\nforged is not a target" })
      .to eq([1, "relspec: error: x\\e[31m\\nforged is not a target\n"])
  end

  it "keeps the lines of other errors (a tool's output) and escapes what is in them" do
    expect(run { raise Relspec::PublishError, "reprepro failed:\n\e[2Jgone" })
      .to eq([1, "relspec: error: reprepro failed:\n\\e[2Jgone\n"])
    stderr.truncate(0)
    stderr.rewind
    expect(run { raise Errno::ENOENT, "/tmp/a\e[31m" }).to eq([1, "relspec: error: No such file or directory - /tmp/a\\e[31m\n"])
    stderr.truncate(0)
    stderr.rewind
    # a file name that is not UTF-8 in a message of several lines: still a user error
    expect(run { raise Relspec::ToolError, "tar failed:\ncaf\xE9" }).to eq([1, "relspec: error: tar failed:\ncaf\\xE9\n"])
  end

  it "prints diagnostics with their summary, and a bug as one line asking for --debug" do
    diagnostic = Relspec::Diagnostic.error("r", "bad", location: Relspec::Location.file_only("s\e.yml"))
    expect(run { raise Relspec::InvalidInput, [diagnostic] }).to eq([1, "s\\e.yml: error[r]: bad\n1 error in 1 file\n"])
    stderr.truncate(0)
    stderr.rewind
    status, text = run { raise ArgumentError, "odd\e" }
    expect([status, text.lines.first]).to eq([70, "relspec: internal error: ArgumentError: odd\\e\n"])
  end
end
