# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/build_dependency_set"

# The exact build-dependency set read from apt-get --simulate's output (the
# lines below are apt 2.6's, from a real run; apt resolves for real in
# spec/relspec/builder/build_dependency_set_spec.rb).
RSpec.describe Relspec::Builder::BuildDependencySet do
  def simulation(*inst)
    "Reading package lists...\nThe following NEW packages will be installed:\n  x\n" \
      "#{inst.map { |line| "#{line}\n" }.join}Conf rel-base (2:0.5~rc1-1 bookworm [all])\n"
  end

  def set(*inst)
    described_class.from_simulation(simulation(*inst), source: "sbuild of base/small")
  end

  let(:base) { "Inst rel-base (2:0.5~rc1-1 bookworm [all])" }
  let(:cmake) { "Inst rel-cmake [0.9-1] (1.0-1 Debian:12.11/stable, Debian-Security:12/stable-security [amd64]) []" }

  it "reads the packages apt would unpack, with their versions and architectures, in a fixed order" do
    expect(set(cmake, base).install_arguments).to eq(["rel-base:all=2:0.5~rc1-1", "rel-cmake:amd64=1.0-1"])
    expect(set(cmake, base)).to be_frozen
    expect(set(cmake, base).packages).to all(be_frozen)
    expect(set("Inst libc6:i386 (2.36-9 bookworm [i386])").install_arguments).to eq(["libc6:i386=2.36-9"])
    expect(set).to be_empty
  end

  it "has one key per exact set: the same whatever apt's order, another for any other package or version" do
    expect(set(cmake, base)).to eq(set(base, cmake))
    expect(set(cmake, base).key).to eq(set(base, cmake).key)
    expect(set(cmake, base).key).to match(/\A\h{64}\z/)
    others = [set(base), set(cmake), set(cmake.sub("1.0-1", "1.0-2"), base), set(cmake, base.sub("[all]", "[amd64]")),
              set(cmake, base, "Inst rel-extra (1 bookworm [all])")]
    others.each do |other|
      expect(other).not_to eq(set(cmake, base))
      expect(other.key).not_to eq(set(cmake, base).key)
    end
    expect({ set(cmake, base) => 1 }).to have_key(set(base, cmake))
  end

  it "refuses a name, version or architecture from an index that could not name a package" do
    ["Inst -o=x (1 bookworm [all])", "Inst rel-base (1;rm bookworm [all])", "Inst rel-base (1 bookworm [../x])",
     "Inst rel-base (\e[2J1 bookworm [all])"].each do |line|
      expect { set(line) }.to raise_error(Relspec::BuildError, %r{\Asbuild of base/small: apt would install a package with the })
    end
    expect { set("Inst rel-base (\e[2J1 bookworm [all])") }
      .to raise_error(Relspec::BuildError, 'sbuild of base/small: apt would install a package with the version "\e[2J1"')
  end

  it "simulates the Build-Depends with what sbuild adds to every build" do
    expect(described_class.simulate_arguments(["rel-cmake (>= 1.0)", "pkg-config"]))
      .to eq(["--simulate", "--no-install-recommends", "satisfy", "rel-cmake (>= 1.0)", "pkg-config",
              "build-essential, fakeroot"])
  end
end
