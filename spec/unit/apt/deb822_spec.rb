# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/deb822"
require "relspec/apt/packages_scanner"

RSpec.describe Relspec::Apt::Deb822 do
  it "reads stanzas, continuation lines and comments, with the line each starts on" do
    text = "# a comment\nPackage: a\nDescription: short\n long\n .\n more\n\n\nPackage: b\nVersion: 1\n"
    stanzas, lines = described_class.parse_with_lines(text)
    expect(stanzas).to eq([{ "Package" => "a", "Description" => "short\n long\n .\n more" },
                           { "Package" => "b", "Version" => "1" }])
    expect(lines).to eq([2, 9])
  end

  it "accepts CRLF line ends" do
    expect(described_class.parse("A: 1\r\nB: 2\r\n\r\nC: 3\r\n")).to eq([{ "A" => "1", "B" => "2" }, { "C" => "3" }])
  end

  {
    "Package: a\nthis is not a field\n" => "line 2: expected \"Field: value\", found \"this is not a field\"",
    " leading continuation\n" => "line 1: continuation line outside of a field",
    "A: 1\nA: 2\n" => "line 2: field A appears twice in one stanza",
    ": no name\n" => "line 1: expected \"Field: value\", found \": no name\""
  }.each do |text, message|
    it "refuses #{text.lines.first.strip.inspect} with its line number" do
      expect { described_class.parse(text) }.to raise_error(Relspec::Apt::Deb822::ParseError, message)
      expect { described_class.parse_in_ruby(text) }.to raise_error(Relspec::Apt::Deb822::ParseError, message)
    end
  end

  it "separates stanzas at a line of only spaces or tabs, in the C reader and the Ruby scanner alike" do
    text = "Package: a\nVersion: 1\n \t\nPackage: b\nVersion: 2\n"
    scanner = Relspec::Apt::PackagesScanner.new(text)
    expected = [{ "Package" => "a", "Version" => "1" }, { "Package" => "b", "Version" => "2" }]
    expect(scanner.each_in_ruby(%w[Package Version]).to_a).to eq(expected)
    expect(scanner.each(%w[Package Version]).to_a).to eq(expected)
  end

  it "is read by the C reader, compiled by bin/setup" do
    expect(Relspec::Apt::NativeReader.available?).to be(true)
  end

  it "reads the same in C and in Ruby: values, lines, continuations, comments, CRLF, UTF-8" do
    random = Random.new(7)
    text = Array.new(3000) do |i|
      lines = ["Package: p#{i}", "Version: 1.#{i}", "Maintainer: Gürkan #{i} <g@example.org>"]
      lines << "Description: short #{i}  \n long\n .\n\tmore" if random.rand(2).zero?
      lines << "Depends: a,\n b (>= 1)" if random.rand(3).zero?
      lines << "# a comment" if random.rand(10).zero?
      lines << "X-Empty:" if random.rand(10).zero?
      lines.shuffle(random: random).join(random.rand(8).zero? ? "\r\n" : "\n")
    end.join("\n\n \t\n")
    # the C reader is loaded on first use (NativeReader), not by the require above
    expect(Relspec::Apt::NativeReader.available?).to be(true)
    expect(Relspec::Apt::Native.parse(text.b)).to eq(described_class.parse_in_ruby(text.b))
    scanner = Relspec::Apt::PackagesScanner.new(text.b)
    fields = %w[Package Version Depends Description]
    expect(scanner.each(fields).to_a).to eq(described_class.parse(text.b).map { |stanza| stanza.slice(*fields) })
    yielded = []
    described_class.each(text.b) { |stanza, line| yielded << [stanza, line] }
    stanzas, lines = described_class.parse_in_ruby(text.b)
    expect(yielded).to eq(stanzas.zip(lines))
  end
end

RSpec.describe Relspec::Apt::PackagesScanner do
  fields = %w[Package Version Depends Provides Source]

  # A Packages-like text with fields in varying order, optional fields,
  # continuation lines and extra blank lines.
  def generated(count)
    random = Random.new(42)
    Array.new(count) do |i|
      lines = ["Package: p#{i}", "Version: 1.#{i}-1"]
      lines << "Depends: p#{i - 1} (>= 1.0), libc6" if random.rand(2).zero? && i.positive?
      lines << "Provides: virtual-#{i % 7}" if random.rand(5).zero?
      lines << "Source: src#{i % 11} (1.0)" if random.rand(3).zero?
      lines << "Description: package #{i}\n long text\n .\n more"
      lines.insert(1, lines.delete_at(-1)) if random.rand(2).zero?
      lines.join("\n")
    end.join("\n\n") + "\n"
  end

  it "gives the same fields as the full parser" do
    text = generated(2000)
    full = Relspec::Apt::Deb822.parse(text).map { |stanza| stanza.slice(*fields) }
    expect(described_class.new(text.b).each(fields).to_a).to eq(full)
  end

  it "reads a field that starts a stanza, and continuation lines of wanted fields" do
    text = "Version: 2\nPackage: a\nDepends: b,\n c\n\nPackage: z\n"
    expect(described_class.new(text).each(%w[Package Version Depends]).to_a)
      .to eq([{ "Version" => "2", "Package" => "a", "Depends" => "b,\n c" }, { "Package" => "z" }])
  end

  it "falls back to the full parser for comments and CRLF" do
    text = "# c\r\nPackage: a\r\nVersion: 1\r\n"
    expect(described_class.new(text).each(%w[Package Version]).to_a).to eq([{ "Package" => "a", "Version" => "1" }])
  end
end
