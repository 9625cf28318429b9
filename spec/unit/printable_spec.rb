# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/printable"

RSpec.describe Relspec::Printable do
  it "escapes control characters and bidirectional overrides, and keeps the rest" do
    expect(described_class.text("needs qt4\nforged\e[2J\r\t\u007F\u0085 \u202Eevil \u2066 é ü"))
      .to eq("needs qt4\\nforged\\e[2J\\r\\t\\u007F\\u0085 \\u202Eevil \\u2066 é ü")
  end

  it "writes bytes that are not UTF-8 as \\x escapes" do
    expect(described_class.text("a\xFFb".b)).to eq("a\\xFFb")
    expect(described_class.text("plain")).to eq("plain")
    expect(described_class.text(nil)).to eq("")
  end

  it "keeps the line breaks of text of several lines and escapes the rest of each line" do
    expect(described_class.lines("reprepro failed:\n\e[2Jcannot\tread\r\n")).to eq("reprepro failed:\n\\e[2Jcannot\tread\\r\n")
    expect(described_class.lines("already\\e escaped")).to eq("already\\e escaped")
    expect(described_class.lines("caf\xE9\n\e".b)).to eq("caf\\xE9\n\\e") # not UTF-8: no ArgumentError from split
  end
end
