# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/package_index"
require "relspec/plan/archive_versions"

# The versions planning keeps of a distribution's Packages index, fed a
# small index in memory.
RSpec.describe Relspec::Plan::ArchiveVersions do
  let(:index) do
    Relspec::Apt::PackageIndex.parse(<<~INDEX)
      Package: ruby-thor
      Version: 1.2.1-1

      Package: libruby3.1
      Version: 3.1.2-7+deb12u1
      Provides: ruby-date (= 3.2.2), ruby-json (= 2.6.1), ruby-unversioned

      Package: ruby-thor
      Version: 1.0.0-1

      Package: broken
      Version: 1.0
      Provides: ruby-oops (= 1.0, ((
    INDEX
  end

  it "keeps each package's newest version and the versions provided with =" do
    versions = described_class.from_index(index)
    expect(versions.names).to contain_exactly("ruby-thor", "libruby3.1", "broken")
    expect(versions.version("ruby-thor")).to eq("1.2.1-1")
    expect(versions.version("ruby-date")).to be_nil
    expect(versions.enum_for(:each_provided, /\Aruby-/).to_a).to eq([%w[ruby-date 3.2.2], %w[ruby-json 2.6.1]])
    expect(versions.enum_for(:each_provided, %w[ruby-json]).to_a).to eq([%w[ruby-json 2.6.1]])
  end

  it "reads back what it wrote, and nothing of an entry changed since" do
    dump = described_class.from_index(index).dump
    loaded = described_class.load(dump)
    expect(loaded.names).to eq(described_class.from_index(index).names)
    expect(loaded.version("libruby3.1")).to eq("3.1.2-7+deb12u1")
    expect(loaded.enum_for(:each_provided, /\Aruby-/).to_a).to eq([%w[ruby-date 3.2.2], %w[ruby-json 2.6.1]])
    expect(loaded.dump).to eq(dump)

    expect(described_class.load(dump.sub("1.2.1-1", "9.9.9-1"))).to be_nil
    expect(described_class.load(dump[0...-10])).to be_nil
    expect(described_class.load("")).to be_nil
    expect(described_class.load(nil)).to be_nil
  end
end
