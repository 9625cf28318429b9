# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/apt/package_index"
require "relspec/plan/target"
require "digest"
require "relspec/plan/distribution_packages"

# What planning keeps of a distribution's archive, fed a small index in
# memory: the repository and the archive stand for Apt::Repository and the
# spec's archive value with the two calls that read an index (the readers
# themselves have their own specs).
RSpec.describe Relspec::Plan::DistributionPackages do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:index) do
    Relspec::Apt::PackageIndex.parse(<<~INDEX)
      Package: ruby-minitest
      Version: 5.17.0-1

      Package: libruby3.1
      Version: 3.1.2-7+deb12u1
      Provides: ruby-minitest (= 5.15.0), ruby-date (= 3.2.2)

      Package: libruby3.1-extra
      Version: 1
      Provides: ruby-minitest (= 5.15.0)
    INDEX
  end
  # +indices+: arch => PackageIndex, the architectures apt reads in order.
  def reader(indices)
    Struct.new(:indices) do
      def index_architectures(_codename, _arch, **)
        indices.keys
      end

      def index_digest(_codename, arch, **)
        Digest::SHA256.hexdigest(arch)
      end

      def packages(_codename, arch, **)
        indices.fetch(arch)
      end
    end.new(indices)
  end
  let(:repository) { reader("amd64" => index) }
  let(:archive) { Struct.new(:read_components).new(["main"]) }

  it "keeps every version of a name, the package's and those provided, newest first" do
    found, = described_class.send(:versions, repository, archive, target, %w[ruby-minitest ruby-date ruby-none],
                                  Relspec::Apt::Cache.new(nil))
    expect(found).to eq("ruby-minitest" => %w[5.17.0-1 5.15.0], "ruby-date" => ["3.2.2"])
    packages = described_class.new({ target => found }, [])
    expect(packages.version_of("ruby-minitest", target)).to eq("5.17.0-1")
    expect(packages.versions_of("ruby-minitest", target)).to eq(%w[5.17.0-1 5.15.0])
    expect(packages.versions_of("ruby-none", target)).to eq([])
  end

  it "reads binary-all too where apt reads one: a ruby-<gem> is Architecture: all" do
    all = Relspec::Apt::PackageIndex.parse("Package: ruby-facets\nVersion: 3.1.0-3\n")
    found, = described_class.send(:versions, reader("amd64" => index, "all" => all), archive, target,
                                  %w[ruby-facets ruby-minitest], Relspec::Apt::Cache.new(nil))
    expect(found).to eq("ruby-facets" => ["3.1.0-3"], "ruby-minitest" => %w[5.17.0-1 5.15.0])
    expect(described_class.send(:versions, repository, archive, target, %w[ruby-facets], Relspec::Apt::Cache.new(nil)).first)
      .to eq({})
  end

  it "keeps what every gem package depends on, whatever names are wanted: the newest of a name over the indices" do
    amd64 = Relspec::Apt::PackageIndex.parse("Package: ruby-types\nVersion: 1.2.2-2\nDepends: ruby-core (>= 0.4.4), libc6\n")
    all = Relspec::Apt::PackageIndex.parse("Package: ruby-types\nVersion: 1.0-1\nDepends: ruby-old\n\n" \
                                           "Package: ruby-web\nVersion: 1.6.2-3\nDepends: ruby-types | ruby-core\n")
    _, depends = described_class.send(:versions, reader("all" => all, "amd64" => amd64), archive, target, %w[ruby-none],
                                      Relspec::Apt::Cache.new(nil))
    expect(depends.transform_values(&:to_h))
      .to eq("ruby-types" => { name: "ruby-types", version: "1.2.2-2", depends: ["ruby-core"] },
             "ruby-web" => { name: "ruby-web", version: "1.6.2-3", depends: %w[ruby-core ruby-types] })
    packages = described_class.new({ target => {} }, [], {}, { target => depends })
    expect(packages.gem_depends(target).keys).to eq(%w[ruby-types ruby-web])
    expect(packages.gem_depends(Relspec::Plan::Target.new("trixie", "amd64"))).to eq({})
  end
end
