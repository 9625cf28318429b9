# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/autoproj_osdeps"

RSpec.describe Relspec::Catalog::AutoprojOsdeps do
  it "finds the keys autoproj splits into a part with a space, at any depth" do
    definition = { "ubuntu, debian" => "libfoo-dev", "gentoo" => { "default" => "x" },
                   "debian" => { "bookworm ,trixie" => "y", "bullseye,buster" => "z" } }
    expect(described_class.spaced_keys(definition)).to eq(["ubuntu, debian", "bookworm ,trixie"])
    expect(described_class.spaced_keys("ignore")).to eq([])
  end
end
