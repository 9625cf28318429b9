# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/catalog"

RSpec.describe Relspec::Catalog do
  let(:catalog) do
    described_class.new(packages: {}, metapackages: { "rock" => ["a"] }, excluded: ["ocl"], codenames: ["bookworm"],
                        exclusion_reasons: { "ocl" => "USE_OCL is false" }, weak_metapackages: ["rock"])
  end

  it "keeps exclusion reasons and weak metapackages when its packages change" do
    copy = catalog.with_packages({})
    expect(copy).to eq(catalog)
    expect(copy.weak?("rock")).to be(true)
    expect(copy.to_h.slice("exclusion_reasons", "weak_metapackages"))
      .to eq("exclusion_reasons" => { "ocl" => "USE_OCL is false" }, "weak_metapackages" => ["rock"])
  end

  it "writes neither when there is none, so older snapshots stay byte for byte" do
    expect(described_class.new(packages: {}).to_h.keys).to eq(%w[codenames layout excluded ignored metapackages packages])
  end
end
