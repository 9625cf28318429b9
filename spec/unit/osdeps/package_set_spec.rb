# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/osdeps/package_set"

# A repository's osdeps file is checked before the package set ships it.
RSpec.describe Relspec::Osdeps::PackageSet do
  def problems(text)
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "a-amd64.yml"), text)
      described_class.osdeps_problems(File.join(dir, "a-amd64.yml")).map(&:message)
    end
  end

  it "accepts an osdeps file of Debian package names" do
    expect(problems("base/cmake:\n  debian:\n    12,bookworm: rock-a-base-cmake\n")).to eq([])
  end

  it "names each package whose Debian name is not one, and refuses other shapes" do
    expect(problems("b:\n  debian:\n    12,bookworm: \"-oX=y\"\na:\n  debian:\n    12,bookworm: \"a b\"\n"))
      .to eq(["a: \"a b\" is not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)",
              "b: \"-oX=y\" is not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)"])
    expect(problems("a: rock-a\n")).to eq(["a: is not a mapping of OS types"])
    expect(problems("[a\n").first).to start_with("is not plain YAML")
  end
end
