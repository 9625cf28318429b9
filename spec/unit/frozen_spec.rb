# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/frozen"

RSpec.describe Relspec::Frozen do
  it "freezes mappings, lists and text all the way down, as copies" do
    text = +"x"
    value = { +"a" => [text, { "b" => +"c" }], "n" => 1, "none" => nil }
    frozen = described_class.deep(value)
    expect(frozen).to eq(value)
    expect([frozen, frozen["a"], frozen["a"][0], frozen["a"][1], frozen["a"][1]["b"], frozen.keys.first]).to all(be_frozen)
    expect([value, value["a"], text]).to all(satisfy { |item| !item.frozen? })
  end
end
