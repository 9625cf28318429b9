# frozen_string_literal: true

require "relspec/release_specs/distribution"

RSpec.describe Relspec::ReleaseSpec::Distributions do
  describe ".builtin" do
    it "is every built-in distribution without a list, the named ones in the order named" do
      expect(described_class.builtin(nil).keys).to include("bionic", "bookworm", "noble")
      expect(described_class.builtin("bookworm, bionic").keys).to eq(%w[bookworm bionic])
    end

    it "refuses an unknown name, naming the known ones" do
      expect { described_class.builtin("bookworm,trixie") }
        .to raise_error(Relspec::InvalidOption, /\Aunknown distribution "trixie" \(known: xenial, bionic,/)
    end
  end
end
