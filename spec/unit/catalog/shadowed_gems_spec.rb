# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_depends"
require "relspec/catalog/shadowed_gems"

# Which distribution gems the release's own gems shadow, over a small
# dependency graph in memory (trixie's dry-* family).
RSpec.describe Relspec::Catalog::ShadowedGems do
  def depends(name, version, *names)
    [name, Relspec::Catalog::GemDepends.new(name: name, version: version, depends: names)]
  end

  let(:graph) do
    [depends("ruby-dry-types", "1.2.2-2", "ruby-concurrent", "ruby-dry-core", "ruby-dry-logic"),
     depends("ruby-dry-logic", "1.2.0-3", "ruby-dry-core"),
     depends("ruby-grape", "1.6.2-3", "ruby-dry-types", "ruby-mustermann"),
     depends("ruby-loop-a", "1.0-1", "ruby-loop-b"), depends("ruby-loop-b", "1.0-1", "ruby-loop-a"),
     depends("rake-compiler", "1.2.5-2", "rake")].to_h
  end

  def shadows(packaged)
    described_class.new(depends: graph, packaged: packaged, codename: "trixie")
  end

  it "names the packaged gem a distribution gem depends on, directly or through other gem packages" do
    found = shadows("dry-core" => "1.2.0")
    expect(found.of("ruby-dry-types").to_s)
      .to eq("ruby-dry-types 1.2.2-2 (trixie) depends on dry-core, which the release packages at 1.2.0")
    expect(found.of("ruby-grape").to_s).to eq("ruby-grape 1.6.2-3 (trixie) depends on ruby-dry-types, which depends on " \
                                              "dry-core, which the release packages at 1.2.0")
    expect(found.of("ruby-grape")).to be_frozen
    expect(found.of("ruby-grape").via).to eq(["ruby-dry-types"])
  end

  it "finds the shortest chain, and the gem's Debian name as Debian gives it (concurrent-ruby is ruby-concurrent)" do
    expect(shadows("dry-core" => "1.2.0", "dry-logic" => "1.6.0").of("ruby-dry-types").gem).to eq("dry-core")
    expect(shadows("concurrent-ruby" => "1.3.8").of("ruby-grape").to_s)
      .to eq("ruby-grape 1.6.2-3 (trixie) depends on ruby-dry-types, which depends on concurrent-ruby, which the release " \
             "packages at 1.3.8")
    expect(shadows("rake" => "13.0").of("rake-compiler").gem).to eq("rake")
  end

  it "shadows nothing that reaches no packaged gem, ends on a cycle, and knows no package the archive lacks" do
    found = shadows("mustermann" => "4.0.1")
    expect(found.of("ruby-dry-types")).to be_nil
    expect(found.of("ruby-loop-a")).to be_nil
    expect(found.of("ruby-none")).to be_nil
    # a package that is itself packaged is not its own shadow
    expect(shadows("dry-types" => "1.9.1").of("ruby-dry-types")).to be_nil
  end
end
