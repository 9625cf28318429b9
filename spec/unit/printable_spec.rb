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
end
