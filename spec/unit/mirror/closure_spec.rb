# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/mirror/binary_index"
require "relspec/mirror/closure"

RSpec.describe Relspec::Mirror::Closure do
  def index(*stanzas)
    text = stanzas.map do |name, version, extra|
      "Package: #{name}\nVersion: #{version}\nArchitecture: all\n#{extra}Filename: pool/#{name}.deb\nSize: 1\n" \
        "SHA256: #{'0' * 64}\n\n"
    end.join
    Relspec::Mirror::BinaryIndex.new.add(text, origin: nil, where: "Packages")
  end

  it "follows every alternative and every provider, transitively, and nothing else" do
    index = index(["app", "1", "Depends: lib-a | lib-b, mta\n"], ["lib-a", "1", "Depends: base\n"], %w[lib-b 1],
                  ["exim", "1", "Provides: mta\n"], ["postfix", "1", "Provides: mta\n"], %w[base 1], %w[other 1])
    closure = described_class.of(index, ["app"])
    expect(closure.names).to eq(%w[app base exim lib-a lib-b postfix])
    expect(closure.missing).to eq([])
    expect(closure.needed_by["base"]).to eq("lib-a 1")
  end

  it "keeps versioned relations: an old version or an unversioned Provides does not satisfy them" do
    index = index(["app", "1", "Depends: lib (>= 2), virt (= 3)\n"], %w[lib 1], ["prov", "1", "Provides: virt\n"])
    closure = described_class.of(index, ["app"])
    expect(closure.names).to eq(["app"])
    expect(closure.missing.map(&:to_s)).to eq(["lib (>= 2) (needed by app 1)", "virt (= 3) (needed by app 1)"])
  end

  it "takes a versioned Provides that fits, and Pre-Depends" do
    index = index(["app", "1", "Pre-Depends: pre\nDepends: virt (>= 3)\n"], %w[pre 1], ["prov", "1", "Provides: virt (= 3.1)\n"])
    expect(described_class.of(index, ["app"]).names).to eq(%w[app pre prov])
  end

  it "names a seed the indices do not have, needed by the release" do
    closure = described_class.of(index(%w[aa 1]), %w[aa gone])
    expect(closure.missing.map(&:to_s)).to eq(["gone (needed by the release)"])
  end
end
