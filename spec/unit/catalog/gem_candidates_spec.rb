# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_candidates"

# The version of a gem to package, in memory: gem_source stands for
# GemVersions (what it lists, what its index says of each version's Ruby),
# the fetch for GemArchive (the .gem's required_ruby_version).
RSpec.describe Relspec::Catalog::GemCandidates do
  let(:listed) { %w[1.2.0 1.1.0 1.0.0].map { |version| Gem::Version.new(version) } }
  let(:hints) { {} }
  let(:gemspecs) { { "1.2.0" => ">= 3.2", "1.1.0" => ">= 3.1.0", "1.0.0" => ">= 2.7" } }
  let(:fetched) { [] }
  let(:versions) do
    Struct.new(:listed, :hints) do
      def of(_name) = listed
      def required_ruby(_name, version) = hints[version.to_s]&.then { |text| Gem::Requirement.new(text) }
    end.new(listed, hints)
  end
  let(:fetch) do
    lambda do |name, version|
      fetched << version
      Struct.new(:name, :version, :required_ruby).new(name, version, Gem::Requirement.new(gemspecs.fetch(version)))
    end
  end
  let(:bookworm) { Relspec::Catalog::TargetRubies.new("bookworm" => "3.1", "trixie" => "3.3") }

  def best(rubies: bookworm, locked: {}, refused: [], &fits)
    fits ||= ->(_) { true }
    described_class.new(versions: versions, fetch: fetch, rubies: rubies, locked: locked)
                   .best("dry-core", refused, &fits)&.version
  end

  it "takes the highest version that fits and every target's Ruby runs, saying which it passed over" do
    refused = []
    expect(best(refused: refused)).to eq("1.1.0")
    expect(refused).to eq([["1.2.0", Gem::Requirement.new(">= 3.2")]])
    expect(best(rubies: Relspec::Catalog::TargetRubies.new("trixie" => "3.3"))).to eq("1.2.0")
    expect(best { |version| version < Gem::Version.new("1.1") }).to eq("1.0.0")
  end

  it "skips what the index says a target's Ruby cannot run without downloading it; the .gem decides the rest" do
    hints.merge!("1.2.0" => ">= 3.2", "1.1.0" => ">= 2.0")
    expect(best).to eq("1.1.0")
    expect(fetched).to eq(["1.1.0"])
  end

  it "keeps the lock's version while it fits, Ruby included" do
    expect(best(locked: { "dry-core" => "1.0.0" })).to eq("1.0.0")
    expect(best(rubies: Relspec::Catalog::TargetRubies.new("bookworm" => "3.0"), locked: { "dry-core" => "1.1.0" })).to eq("1.0.0")
  end

  it "gives nothing when no version does" do
    refused = []
    expect(best(rubies: Relspec::Catalog::TargetRubies.new("buster" => "2.5"), refused: refused)).to be_nil
    expect(refused.map(&:first)).to eq(%w[1.2.0 1.1.0 1.0.0])
  end
end
