# frozen_string_literal: true

require "relspec/debian/control_relations"

RSpec.describe Relspec::Debian::ControlRelations do
  describe ".build_depends" do
    # autoproj's own Ruby is in every workspace: base/cmake's RockRuby finds
    # it there, and a clean chroot must have it too (tools/orogen_metadata
    # stopped at `Could NOT find Ruby` in sbuild without it).
    it "gives CMake and oroGen builds what autoproj installs for itself" do
      %w[cmake orogen].each do |type|
        expect(described_class.build_depends(type, [], [])).to include("ruby-dev")
      end
    end

    it "keeps autoproj's own Ruby out of other build types and out of Depends" do
      expect(described_class.build_depends("autotools", [], [])).not_to include("ruby-dev")
      expect(described_class.build_depends("meta", [], [])).to eq([described_class::DEBHELPER])
      expect(described_class.depends("cmake", "any", [], [])).not_to include("ruby-dev")
    end

    it "writes the dependency closure's build-only tools after the package's own relations, once each" do
      relations = described_class.build_depends("cmake", ["librock-base-cmake (>= 1)"], ["libeigen3-dev"],
                                                closure: %w[pkg-config cmake])
      expect(relations).to eq(["debhelper-compat (= 13)", "cmake", "librock-base-cmake (>= 1)", "libeigen3-dev",
                               "pkg-config", "ruby-dev"])
    end
  end

  describe ".build_only" do
    it "is the build-only part of a build type's tools and its OS dependencies" do
      expect(described_class.build_only("orogen", %w[libboost-dev pkg-config])).to eq(%w[cmake pkg-config])
    end
  end
end
