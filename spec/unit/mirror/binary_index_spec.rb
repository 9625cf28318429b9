# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/mirror/binary_index"

RSpec.describe Relspec::Mirror::BinaryIndex do
  def stanza(name, version: "1.0", filename: nil, sha: "a" * 64, size: "10", extra: "")
    "Package: #{name}\nVersion: #{version}\nArchitecture: amd64\n#{extra}" \
      "Filename: #{filename || "pool/main/#{name[0]}/#{name}/#{name}_#{version}_amd64.deb"}\nSize: #{size}\nSHA256: #{sha}\n\n"
  end

  let(:origin) { Relspec::Mirror::Origin.new(label: "test", fetcher: nil, distribution: true) }

  def index(text)
    described_class.new.add(text, origin: origin, where: "Packages")
  end

  it "keeps the highest version of a name across indices, with its file, checksum and relations" do
    index = index(stanza("aa", version: "1.0", extra: "Pre-Depends: p\nDepends: b | c (>= 2)\nPriority: required\n"))
    index.add(stanza("aa", version: "1.0+deb12u1"), origin: origin, where: "updates")
    index.add(stanza("aa", version: "0.9"), origin: origin, where: "old")
    expect(index["aa"].version).to eq("1.0+deb12u1")
    expect(index["aa"].file_name).to eq("aa_1.0+deb12u1_amd64.deb")

    first = index(stanza("aa", extra: "Pre-Depends: p\nDepends: b | c (>= 2)\nPriority: required\nEssential: no\n"))["aa"]
    expect(first.depends.map { |group| group.map(&:to_s) }).to eq([["p"], ["b", "c (>= 2)"]])
    expect(first).to be_required
  end

  it "finds the providers of a virtual package" do
    index = index(stanza("exim", extra: "Provides: mail-transport-agent\n") + stanza("postfix", extra: "Provides: mail-transport-agent (= 1)\n"))
    expect(index.providers("mail-transport-agent").map { |binary, _| binary.name }).to eq(%w[exim postfix])
    expect(index.providers("nothing")).to eq([])
  end

  {
    "a name with a space" => { name: "bad name" },
    "a file outside the pool" => { filename: "../../etc/passwd.deb" },
    "an absolute file" => { filename: "/etc/x.deb" },
    "a file with shell syntax" => { filename: "pool/a/$(reboot).deb" },
    "a missing checksum" => { sha: "" },
    "a size that is no number" => { size: "12 34" },
    "an invalid version" => { version: "not a version!" }
  }.each do |what, fields|
    it "refuses #{what}, naming the index and the stanza" do
      name = fields.delete(:name) || "pkg"
      expect { index(stanza("ok") + stanza(name, **fields)) }
        .to raise_error(described_class::Invalid, /\APackages, stanza 2/)
    end
  end

  it "keeps a release's package over the distribution's higher version of its name, and says so" do
    release = Relspec::Mirror::Origin.new(label: "g", fetcher: nil, distribution: false)
    index = described_class.new.add(stanza("rock-g", version: "1.0-1"), origin: release, where: "release")
    index.add(stanza("rock-g", version: "9.0-1"), origin: origin, where: "bookworm")
    index.add(stanza("rock-g", version: "9.1-1"), origin: origin, where: "bookworm-updates")
    index.add(stanza("rock-g", version: "0.5-1"), origin: origin, where: "old")
    expect(index["rock-g"].version).to eq("1.0-1")
    expect(index.pinned.map { |pin| [pin.kept.to_s, pin.shadowed.to_s] }).to eq([["rock-g 1.0-1", "rock-g 9.1-1"]])

    # in whichever order the indices come, merged or added
    merged = index(stanza("rock-g", version: "9.0-1")).merge(described_class.new.add(stanza("rock-g", version: "1.0-1"),
                                                                                     origin: release, where: "release"))
    expect([merged["rock-g"].version, merged.pinned.size]).to eq(["1.0-1", 1])
    expect(described_class.new.merge(merged).pinned.map { |pin| pin.shadowed.version }).to eq(["9.0-1"])
    # a lower version of the distribution is no pin
    lower = index(stanza("rock-g", version: "0.1-1")).add(stanza("rock-g", version: "1.0-1"), origin: release, where: "r")
    expect([lower["rock-g"].version, lower.pinned]).to eq(["1.0-1", []])
  end
end
