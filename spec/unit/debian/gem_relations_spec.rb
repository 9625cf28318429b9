# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/control_relations"
require "relspec/catalog/os_dependencies"

# A gem osdep the distribution provides keeps its osdeps constraint in the
# relations debian/control gets (and relspec check looks up).
RSpec.describe Relspec::Debian::GemRelations do
  it "turns each bound of a constraint into a Debian relation" do
    expect(described_class.of("ruby-rice", "<4.0.0")).to eq(["ruby-rice (<< 4.0.0)"])
    expect(described_class.of("ruby-x", ">= 1.0, <= 2.1, > 0.5, = 1.1"))
      .to eq(["ruby-x (>= 1.0)", "ruby-x (<= 2.1)", "ruby-x (>> 0.5)", "ruby-x (= 1.1)"])
  end

  it "reads ~> as RubyGems does, and a prerelease so that it sorts before its release" do
    expect(described_class.of("ruby-foo", "~> 1.2")).to eq(["ruby-foo (>= 1.2)", "ruby-foo (<< 2)"])
    expect(described_class.of("ruby-foo", "~>1.2.3")).to eq(["ruby-foo (>= 1.2.3)", "ruby-foo (<< 1.3)"])
    expect(described_class.of("ruby-foo", ">= 2.0.0.pre")).to eq(["ruby-foo (>= 2.0.0~pre)"])
    expect(described_class.of("ruby-rice", "= 3.1.pre")).to eq(["ruby-rice (= 3.1~pre)"])
  end

  it "gives the bare name when the constraint says nothing Debian can carry" do
    expect(described_class.of("ruby-bar", "")).to eq(["ruby-bar"])
    expect(described_class.of("ruby-bar", ">= 0")).to eq(["ruby-bar"])
    expect(described_class.of("ruby-bar", "!= 1.5")).to eq(["ruby-bar"])
    expect(described_class.of("ruby-bar", "not a version")).to eq(["ruby-bar"])
  end

  it "is what ControlRelations gives for the distribution's gems, leaving out the release's own" do
    os = Relspec::Catalog::OsDependencies.build(gems: ["rice<4.0.0", "bar", "mine>=1"])
    expect(Relspec::Debian::ControlRelations.distribution_gems(os, ["mine"]))
      .to eq(["ruby-bar", "ruby-rice (<< 4.0.0)"])
  end
end
