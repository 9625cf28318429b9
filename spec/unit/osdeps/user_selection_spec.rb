# frozen_string_literal: true

require_relative "../unit_helper"
require "zlib"
require "relspec/osdeps/user_selection"

# `osdeps select` as a whole: read, select, write both files; nothing
# written when the input is refused.
RSpec.describe Relspec::Osdeps::UserSelection, :tmpdir do
  before do
    File.write(File.join(@dir, "releases.yml"), "rel: ~\n")
    File.write(File.join(@dir, "rel-amd64.yml"),
               "a:\n  debian:\n    12,bookworm: rock-a\nb:\n  debian:\n    12,bookworm: rock-b\n")
    Zlib::GzipWriter.open(File.join(@dir, "Packages.gz")) do |gz|
      gz.write("Package: rock-a\nVersion: 1\nArchitecture: amd64\n\nPackage: rock-b\nVersion: 1\nArchitecture: amd64\nDepends: rock-a\n")
    end
    File.write(File.join(@dir, "deb_blacklist.yml"), "- a\n- gui/none\n")
  end

  def select(**overrides)
    described_class.call(release: "rel", arch: "amd64", os: "debian:12,bookworm", data: @dir,
                         blacklist: File.join(@dir, "deb_blacklist.yml"), index: [File.join(@dir, "Packages.gz")],
                         trusted: false, keyring: nil, output: File.join(@dir, "out"), **overrides)
  end

  it "disables the blacklisted package and what depends on it, and reports an entry that matches nothing" do
    unmatched = []
    result = select(unmatched: ->(entry) { unmatched << entry.pattern.source })
    expect(result.selection.active).to eq({})
    expect(result.selection.inactive.keys).to eq(%w[a b])
    expect(unmatched).to eq(["gui/none"])
    expect(File.file?(File.join(@dir, "out", "rock-osdeps.inactive"))).to be(true)
  end

  it "writes nothing when a name is not a Debian one" do
    File.write(File.join(@dir, "rel-amd64.yml"), "a:\n  debian:\n    12,bookworm: \"-o\"\n")
    expect { select }.to raise_error(Relspec::InvalidInput)
    expect(Dir.exist?(File.join(@dir, "out"))).to be(false)
  end

  # Values that become file names or reach messages are refused before
  # anything is read (issue 46, case 14).
  it "refuses a release, an architecture or a system that is no name, before reading the data" do
    nowhere = { data: "/nonexistent", output: "/nonexistent" }
    expect { select(release: "../x", **nowhere) }.to raise_error(Relspec::InvalidOption, '--release "../x" is not a release name')
    expect { select(arch: "amd64\nx", **nowhere) }
      .to raise_error(Relspec::InvalidOption, '--arch "amd64\nx" is not a Debian architecture name')
    expect { select(os: "debian:12\e[2J", **nowhere) }
      .to raise_error(Relspec::InvalidOption, '--os "debian:12\e[2J" holds control characters')
  end

  it "reads the data folder once the names are good" do
    expect { select(data: "/nonexistent", output: "/nonexistent") }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.rule).to eq("missing-osdeps") }
  end
end
