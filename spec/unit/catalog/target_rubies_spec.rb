# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/target_rubies"
require "relspec/release_specs/distribution"

RSpec.describe Relspec::Catalog::TargetRubies do
  let(:rubies) { described_class.new("trixie" => "3.3", "bookworm" => "3.1", "mine" => nil) }

  it "names the targets whose Ruby a gem's required_ruby_version excludes, by codename" do
    expect(rubies.refusing(Gem::Requirement.new(">= 3.2"))).to eq([%w[bookworm 3.1]])
    expect(rubies.refusing(Gem::Requirement.new(">= 3.4"))).to eq([%w[bookworm 3.1], %w[trixie 3.3]])
    expect(rubies.refusing(Gem::Requirement.new("< 3.2"))).to eq([%w[trixie 3.3]])
    expect(rubies.refusing(nil)).to eq([])
    expect(described_class.describe(rubies.refusing(Gem::Requirement.new(">= 3.4")))).to eq("Ruby 3.1 (bookworm), Ruby 3.3 (trixie)")
  end

  # grape 4.1.0 needs Ruby >= 3.3.1: trixie's 3.3.8 runs it, a Ruby known only as "3.3" is not trusted to
  it "compares the Ruby's release where it is known, else the first release of its major.minor" do
    expect(rubies.refusing(Gem::Requirement.new(">= 3.1.0"))).to eq([])
    expect(rubies.refusing(Gem::Requirement.new(">= 3.1.1"))).to eq([%w[bookworm 3.1]])
    released = described_class.new("bookworm" => "3.1.2", "trixie" => "3.3.8")
    expect(released.refusing(Gem::Requirement.new(">= 3.3.1"))).to eq([%w[bookworm 3.1.2]])
    expect(released.refusing(Gem::Requirement.new(">= 3.1.3"))).to eq([%w[bookworm 3.1.2]])
    expect(released.without(["bookworm"]).rubies).to eq("trixie" => "3.3.8")
  end

  it "reads each target's Ruby from the built-in distributions, and checks none it does not know" do
    effective = Struct.new(:targets, :distributions)
                      .new({ "bookworm" => ["amd64"], "trixie" => ["arm64"], "mine" => ["amd64"] },
                           Relspec::ReleaseSpec::Distributions::BUILTIN)
    expect(described_class.of(effective).rubies).to eq("bookworm" => "3.1.2", "trixie" => "3.3.8")
    expect(described_class.of(effective)).to be_frozen
  end
end
