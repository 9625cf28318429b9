# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/yaml/quick_document"

RSpec.describe Relspec::Yaml::QuickDocument do
  it "reads plain data, keeping how scalars that are not text were written" do
    document = described_class.parse("a:\n  \"7\": 20.10\n  b: text\n")
    expect(document.data).to eq("a" => { "7" => 20.1, "b" => "text" })
    expect(document.raw(%w[a 7])).to eq("20.10")
    expect(document.typed_key?(%w[a 7])).to be(false)
  end

  it "leaves to LocatedDocument a key written plain as a number or true (it says where)" do
    expect(described_class.parse("a:\n  7: x\n")).to be_nil
    expect(described_class.parse("true: x\n")).to be_nil
    expect(described_class.parse("a: &x 1\n")).to be_nil
  end
end
