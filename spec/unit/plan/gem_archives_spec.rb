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
      Relspec::Plan::DistributionPackages.new({ target => { "ruby-thor" => %w[1.2.1-1] } }, [])
    end
  end

  it "reads every ruby-* package once when the catalog asks, and hands the same to the planner" do
    expect(archives.call).to eq("bookworm/amd64" => { "ruby-thor" => %w[1.2.1-1] })
    archives.call
    distribution = archives.distribution(["ruby-thor"])
    expect(distribution.versions_of("ruby-thor", target)).to eq(%w[1.2.1-1])
    expect(reads).to eq([Relspec::Debian::Naming::DISTRIBUTION_GEMS])
  end

  it "reads only the wanted names when the catalog did not ask" do
    archives.distribution(["ruby-thor"])
    expect(reads).to eq([["ruby-thor"]])
  end
end
