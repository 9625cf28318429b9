# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/prefix_markers"
require "relspec/catalog/cmake_defines"
require "relspec/catalog/package_environment"

# The packages here stand for Autobuild::Package with the two attributes the
# markers use (name, prefix): autobuild's real ones register themselves
# globally, which the loader's specs exercise (spec/relspec/compile/prefix_defines_spec.rb).
RSpec.describe Relspec::Catalog::PrefixMarkers do
  let(:packages) do
    pkg = Struct.new(:name, :prefix)
    [pkg.new("a", "/ws/install"), pkg.new("a/b", "/ws/install"), pkg.new("c", "/ws/install/c")]
  end
  let(:markers) { described_class.new(packages, prefix_dir: "/ws/install") }

  it "gives each package a prefix of its own while marked, and autoproj's back afterwards" do
    seen = markers.while_marked { packages.map(&:prefix) }
    expect(seen.uniq.size).to eq(3)
    expect(packages.map(&:prefix)).to eq(%w[/ws/install /ws/install /ws/install/c])
  end

  it "gives autoproj's prefixes back when a block fails" do
    expect { markers.while_marked { raise "boom" } }.to raise_error("boom")
    expect(packages.map(&:prefix)).to eq(%w[/ws/install /ws/install /ws/install/c])
  end

  it "writes a marked value with references, or with autoproj's prefixes, telling nested names apart" do
    a, b = markers.while_marked { [packages[0].prefix, packages[1].prefix] }
    value = "#{b}/lib;#{a};#{a}x;/ws/install/share"
    expect(markers.references(value)).to eq("${prefix:a/b}/lib;${prefix:a};#{a}x;/ws/install/share")
    expect(markers.restore(value)).to eq("/ws/install/lib;/ws/install;#{a}x;/ws/install/share")
    expect(value.scan(described_class::REFERENCE)).to eq([])
    expect(markers.references(value).scan(described_class::REFERENCE).flatten).to eq(%w[a/b a])
  end

  it "gives the catalog's defines as references, the package's environment as before" do
    stub_const("Autobuild::CMake", Struct.new(:defines).new({ "GLOBAL" => "/ws/install/share" }))
    autobuild = Struct.new(:name, :prefix, :defines, :env).new("c", "/ws/install/c", {}, [])
    op = Struct.new(:type, :name, :values)
    markers.while_marked do
      autobuild.defines["A_PREFIX"] = packages[0].prefix
      autobuild.env << op.new(:set, "C_DATA", ["#{packages[2].prefix}/share", "#{packages[0].prefix}/x"])
    end
    expect(Relspec::Catalog::CmakeDefines.of(autobuild, root_dir: "/ws", markers: markers))
      .to eq("A_PREFIX" => "${prefix:a}", "GLOBAL" => "$AUTOPROJ_ROOT/install/share")
    expect(Relspec::Catalog::PackageEnvironment.of(autobuild, root_dir: "/ws", markers: markers))
      .to eq([{ "type" => "set", "name" => "C_DATA", "values" => ["$PREFIX/share", "$AUTOPROJ_ROOT/install/x"] }])
  end
end
