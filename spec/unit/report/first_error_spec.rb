# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/report/first_error"

RSpec.describe Relspec::Report::FirstError do
  it "finds the first error of the last command a host build ran, with the lines that continue it" do
    log = <<~LOG
      $ dpkg-checkbuilddeps
      dpkg-checkbuilddeps: error: Unmet build dependencies: rock-x (>= 1.0)
      $ dpkg-buildpackage -us -uc -b -d
      -- compiling with -Werror
      CMake Error at CMakeLists.txt:3 (message):
        types are broken
        on purpose

      make: *** [debian/rules:26: binary] Error 2
    LOG
    expect(described_class.of_text(log)).to eq("CMake Error at CMakeLists.txt:3 (message):\ntypes are broken\non purpose")
  end

  it "reads a log without commands whole (sbuild), and says nil when nothing looks like an error" do
    expect(described_class.of_text("building\nmake: *** [all] Error 1\n")).to eq("make: *** [all] Error 1")
    expect(described_class.of_text("all good\n0 errors\n")).to be_nil
  end

  it "keeps untrusted bytes harmless: invalid UTF-8 replaced, control characters dropped, long lines cut" do
    line = described_class.of_text("error: \xFF\e[31mred\x00#{'x' * 400}\n".b)
    expect(line).to start_with("error: ? [31mred ")
    expect(line.size).to eq(described_class::MAX_CHARS)
    expect(line).to end_with("…")
  end

  it "reads a log as a stream: the rest of an overlong line is skipped, nothing past MAX_BYTES is read" do
    stub_const("#{described_class}::MAX_LINE_BYTES", 16)
    stub_const("#{described_class}::MAX_BYTES", 64)
    # the tail of a 40-byte line is not a line of its own
    expect(described_class.of_text("#{'x' * 30} error: tail\nok\n")).to be_nil
    expect(described_class.of_text("#{'x' * 30}\nerror: here\n")).to eq("error: here")
    expect(described_class.of_text("#{"ok\n" * 21}error: past the bound\n")).to be_nil
  end

  it "forgets an error a later command answered, and collects at most MAX_CONTINUATION lines" do
    expect(described_class.of_text("$ a\nerror: one\n  more\n$ b\nfine\nerror: two\n")).to eq("error: two")
    text = described_class.of_text("error: x\n#{(1..6).map { |n| "  #{n}\n" }.join}")
    expect(text).to eq("error: x\n1\n2\n3\n4")
  end

  it "reads a log file, and nil for none" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "a.log"), "fatal error: x.h: No such file\n")
      expect(described_class.of_file(File.join(dir, "a.log"))).to eq("fatal error: x.h: No such file")
      expect(described_class.of_file(File.join(dir, "missing.log"))).to be_nil
      expect(described_class.of_file(nil)).to be_nil
      File.symlink("a.log", File.join(dir, "link.log"))
      expect { described_class.of_file(File.join(dir, "link.log")) }.to raise_error(Relspec::Error, /link.log is a symbolic link/)
    end
  end
end
