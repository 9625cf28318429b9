# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/osdeps/user_selection"

# `relspec osdeps select`'s values that become file names or reach its
# messages, refused before anything is read (issue 46, case 14).
RSpec.describe Relspec::Osdeps::UserSelection do
  def select(release: "demo-base", arch: "amd64", os: "debian:12,bookworm")
    described_class.call(release: release, arch: arch, os: os, data: "/nonexistent", blacklist: nil, index: [],
                         trusted: false, keyring: nil, output: "/nonexistent")
  end

  it "refuses a release, an architecture or a system that is no name, before reading the data" do
    expect { select(release: "../x") }.to raise_error(Relspec::InvalidOption, '--release "../x" is not a release name')
    expect { select(arch: "amd64\nx") }
      .to raise_error(Relspec::InvalidOption, '--arch "amd64\nx" is not a Debian architecture name')
    expect { select(os: "debian:12\e[2J") }
      .to raise_error(Relspec::InvalidOption, '--os "debian:12\e[2J" holds control characters')
  end

  it "reads the data folder once the names are good" do
    expect { select }.to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.rule).to eq("missing-osdeps") }
  end
end
