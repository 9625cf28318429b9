# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan"

# The distributions' ruby-* packages are read once per plan: all of them
# when loading the catalog asked, else only the names the release needs.
RSpec.describe Relspec::Plan::GemArchives do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:reads) { [] }
  let(:archives) do
    described_class.new([target]) do |wanted|
      reads << wanted
      depends = Relspec::Catalog::GemDepends.new(name: "ruby-thor", version: "1.2.1-1", depends: ["ruby-x"])
      Relspec::Plan::DistributionPackages.new({ target => { "ruby-thor" => %w[1.2.1-1] } }, [], {},
                                              { target => { "ruby-thor" => depends } })
    end
  end

  it "reads every ruby-* package once when the catalog asks, and hands the same to the planner" do
    expect(archives.call).to eq("bookworm/amd64" => { "ruby-thor" => %w[1.2.1-1] })
    archives.call
    distribution = archives.distribution(["ruby-thor"])
    expect(distribution.versions_of("ruby-thor", target)).to eq(%w[1.2.1-1])
    expect(reads).to eq([Relspec::Debian::Naming::DISTRIBUTION_GEMS])
  end

  it "hands the catalog what the gem packages depend on, from the same one reading" do
    expect(archives.depends.transform_values { |found| found.transform_values(&:depends) })
      .to eq("bookworm/amd64" => { "ruby-thor" => ["ruby-x"] })
    archives.call
    expect(reads.size).to eq(1)
  end

  it "reads only the wanted names when the catalog did not ask" do
    archives.distribution(["ruby-thor"])
    expect(reads).to eq([["ruby-thor"]])
  end
end
