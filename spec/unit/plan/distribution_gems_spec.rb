# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan"

# Which gems of a release a target takes from its distribution's archive,
# and what the plan says about the others.
RSpec.describe Relspec::Plan::DistributionGems do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:notes) { [] }

  def gem_package(name, version, gems: [])
    Relspec::Catalog::Package.new(
      name: name, package_set: "gems", build_type: "gem", commit_time: "2020-06-01T00:00:00Z", source_dir: nil,
      version: version, vcs: Relspec::Catalog::Vcs.new(type: "gem", url: "https://rubygems.org", commit: nil),
      os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: gems) }
    )
  end

  def gems(found, requirements: {}, unknown: [], gaps: {}, depends: {})
    distribution = Relspec::Plan::DistributionPackages.new(found, unknown, gaps, depends)
    described_class.new(distribution: distribution, requirements: requirements, notes: notes)
  end

  it "takes a gem at its own version, and never a blacklisted one" do
    chooser = gems({ target => { "ruby-thor" => %w[13.0.6] } })
    decision = chooser.decide(gem_package("thor", "13.0.6"), target, nil)
    expect([decision.kind, decision.deb_name, decision.version]).to eq([:system, "ruby-thor", "13.0.6"])
    expect(chooser.decide(gem_package("thor", "13.0.6"), target, Relspec::Plan::Cause.blacklisted("thor", nil))).to be_nil
    expect(chooser.decide(gem_package("thor", "13.1.0"), target, nil)).to be_nil
    expect(notes).to eq(["bookworm has ruby-thor 13.0.6, the release packages gem thor 13.1.0"])
  end

  it "takes the newest version its requirements accept" do
    chooser = gems({ target => { "ruby-minitest" => %w[5.17.0 5.15.0] } },
                   requirements: { "minitest" => [Gem::Requirement.new("< 5.16")] })
    expect(chooser.decide(gem_package("minitest", "5.15.0"), target, nil).version).to eq("5.15.0")
  end

  it "says what the archive lacks, and where no archive was read" do
    chooser = gems({ target => { "ruby-x" => %w[1.0] } }, unknown: [Relspec::Plan::Target.new("trixie", "amd64")])
    expect(chooser.decide(gem_package("x", "1.0", gems: ["nokogiri"]), target, nil).kind).to eq(:system)
    expect(chooser.decide(gem_package("y", "1.0"), target, nil)).to be_nil
    chooser.note_unavailable(Relspec::Catalog.new(packages: { "x" => gem_package("x", "1.0") }, layout: [], codenames: []))
    expect(notes).to eq(["gem x needs nokogiri, which the bookworm archive lacks as ruby-nokogiri (add it to gems:)",
                         "the bookworm archive has no ruby-y: gem y is packaged here",
                         "gems are packaged here on trixie: no distribution archive to take ruby-* packages from " \
                         "(distributions.<codename>.archive)"])
  end

  def depends(name, version, *names)
    [name, Relspec::Catalog::GemDepends.new(name: name, version: version, depends: names)]
  end

  # bookworm's ruby-grape-logging depends on ruby-grape, the release builds grape 4.1.0 there;
  # ruby-extra depends on ruby-grape-logging, given up too
  it "gives up a distribution gem that depends on a gem the release gives itself there, and what depends on it" do
    chooser = gems({ target => { "ruby-grape-logging" => %w[1.8.4-1], "ruby-extra" => %w[1.0-1], "ruby-thor" => %w[1.2.1-1] } },
                   depends: { target => [depends("ruby-grape-logging", "1.8.4-1", "ruby-grape"),
                                         depends("ruby-extra", "1.0-1", "ruby-grape-logging"),
                                         depends("ruby-thor", "1.2.1-1", "ruby-other")].to_h })
    packages = [gem_package("grape", "4.1.0"), gem_package("grape_logging", "1.8.4"), gem_package("extra", "1.0"),
                gem_package("thor", "1.2.1")]
    system = packages.drop(1).to_h { |package| [package.name, chooser.decide(package, target, nil)] }
    expect(system.values.map(&:kind)).to eq(%i[system system system])
    shadowed = chooser.shadowed(system, packages, target)
    expect(shadowed.transform_values(&:to_s))
      .to eq("grape_logging" => "ruby-grape-logging 1.8.4-1 (bookworm) depends on grape, which the release packages at 4.1.0",
             "extra" => "ruby-extra 1.0-1 (bookworm) depends on ruby-grape-logging, which depends on grape, which the " \
                        "release packages at 4.1.0")
    expect(notes).to include("ruby-grape-logging 1.8.4-1 (bookworm) depends on grape, which the release packages at 4.1.0: " \
                             "gem grape_logging is packaged here")
    # nothing of the release built there: everything stays the distribution's
    expect(chooser.shadowed(system, packages.drop(1), target)).to eq({})
  end
end
