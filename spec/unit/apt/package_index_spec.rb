# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/package_index"

RSpec.describe Relspec::Apt::PackageIndex do
  it "keeps each name's highest version" do
    index = described_class.parse("Package: a\nVersion: 1.0-1\n\nPackage: a\nVersion: 2.0-1\n")
    expect([index.names, index["a"].version]).to eq([["a"], "2.0-1"])
  end

  it "names a stanza with an invalid version, the index's text escaped" do
    expect { described_class.parse("Package: evil\e[2J\nVersion: not valid\n") }
      .to raise_error(described_class::Invalid, 'stanza 1 (Package: evil\\e[2J) has an invalid Version "not valid"')
  end
end
