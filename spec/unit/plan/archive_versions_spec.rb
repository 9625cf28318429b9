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

      Package: ruby-types
      Version: 1.2.2-2
      Depends: ruby-core (>= 0.4.4), libc6, ruby-concurrent | ruby-concurrent-compat, ruby:any

      Package: ruby-plain
      Version: 1.0-1
      Depends: libc6

      Package: ruby-forged
      Version: 1.0-1
      Depends: ruby-core (>= 1.0, ((
    INDEX
  end

  it "keeps each package's newest version and the versions provided with =" do
    versions = described_class.from_index(index)
    expect(versions.names).to contain_exactly("ruby-thor", "libruby3.1", "broken", "ruby-types", "ruby-plain", "ruby-forged")
    expect(versions.version("ruby-thor")).to eq("1.2.1-1")
    expect(versions.version("ruby-date")).to be_nil
    expect(versions.enum_for(:each_provided, /\Aruby-/).to_a).to eq([%w[ruby-date 3.2.2], %w[ruby-json 2.6.1]])
    expect(versions.enum_for(:each_provided, %w[ruby-json]).to_a).to eq([%w[ruby-json 2.6.1]])
  end

  it "keeps the gem packages each gem package depends on, every alternative" do
    versions = described_class.from_index(index)
    expect(versions.gem_depends("ruby-types")).to eq(%w[ruby-concurrent ruby-concurrent-compat ruby-core])
    expect(versions.gem_depends("ruby-plain")).to eq([])
    # a Depends field this reader cannot parse depends on nothing (the archive is untrusted)
    expect(versions.gem_depends("ruby-forged")).to eq([])
    expect(versions.gem_depends("libruby3.1")).to eq([])
    expect(versions.enum_for(:each_gem_depends).to_a).to eq([["ruby-types", %w[ruby-concurrent ruby-concurrent-compat ruby-core]]])
    loaded = described_class.load(versions.dump)
    expect(loaded.gem_depends("ruby-types")).to eq(%w[ruby-concurrent ruby-concurrent-compat ruby-core])
    # an entry an older relspec wrote, without them, is made again
    old = versions.dump.split("\n", 2).last.sub(/#{described_class::DEPENDS_SEPARATOR}\n.*\z/m, "")
    expect(described_class.load(signed(old))).to be_nil
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

  it "leaves out a name no line of the entry can hold" do
    spaced = Relspec::Apt::PackageIndex.parse("Package: extra foo\nVersion: 1.0-1\n\nPackage: ok\nVersion: 2.0-1\n")
    versions = described_class.from_index(spaced)
    expect(versions.names).to eq(["ok"])
    expect(described_class.load(versions.dump).names).to eq(["ok"])
  end

  def signed(body)
    "#{Digest::SHA256.hexdigest(body)}\n#{body}"
  end

  it "reads nothing of an entry with one bad line, even with the right checksum" do
    provided = "#{described_class::SEPARATOR}\nruby-date 3.2.2\n"
    good = "ruby-thor 1.2.1-1\n#{provided}#{described_class::DEPENDS_SEPARATOR}\nruby-thor ruby-x\n"
    expect(described_class.load(signed(good)).version("ruby-thor")).to eq("1.2.1-1")
    expect(described_class.load(signed(good)).gem_depends("ruby-thor")).to eq(["ruby-x"])
    ["zzz\n#{good}", "extra foo 1.13.10+dfsg-2+b1\n#{good}", "bad\tname 1.0\n#{good}", "x not-a-version\n#{good}",
     "#{good}ruby-json\n", "ruby-thor 1.2.1-1\n", "x 1.0\xff\n#{good}", "ruby-thor 1.2.1-1\n#{provided}ruby-json\n",
     "#{good}ruby-alone\n", "#{good}ruby-a\truby-b\n", "#{good}ruby-a  ruby-b\n"].each do |body|
      expect(described_class.load(signed(body))).to be_nil, body.inspect
    end
  end
end
