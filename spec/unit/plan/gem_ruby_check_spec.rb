# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/gem_ruby_check"
require "relspec/plan/decision"
require "relspec/plan/cause"
require "relspec/plan/target"
require "relspec/catalog/gem_archive"
require "relspec/catalog/shadowed_gems"
require "relspec/release_specs"
require_relative "../../support/in_process_gem"

# A plan whose decisions build a gem on a target whose Ruby cannot load it:
# a real spec (bookworm: Ruby 3.1, trixie: 3.3) and a real .gem (core 1.3.0
# needs Ruby >= 3.2) in a temporary folder; the plan's decisions in memory.
RSpec.describe Relspec::Plan::GemRubyCheck do
  around do |example|
    Dir.mktmpdir("relspec-gem-ruby-check") do |dir|
      @dir = dir
      example.run
    end
  end

  let(:resolution) do
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rel.yml"),
               "release: rel\nworkspace: ../catalog.yml\ntargets: { bookworm: [amd64], trixie: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\ngem_source: ../gems\n")
    Relspec::ReleaseSpec.resolve(File.join(@dir, "specs", "rel.yml"))
  end
  let(:release_catalog) do
    path = InProcessGem.write(File.join(@dir, "gems"), "core", "1.3.0", ruby: ">= 3.2")
    Struct.new(:gems).new({ "core" => Relspec::Catalog::GemArchive.new("core", "1.3.0", path, path) })
  end

  def plan(kinds)
    targets = kinds.to_h do |target, kind|
      cause = kind == :build ? Relspec::Plan::Cause.shadowed_gem("ruby-web 1.6.2-3 (bookworm) depends on core, which the release packages at 1.3.0") : nil
      decision = Relspec::Plan::Decision.new(package: "core", kind: kind, deb_name: "rock-rel-ruby-core", version: "1.3.0-1", cause: cause)
      [Relspec::Plan::Target.parse(target), { "core" => decision }]
    end
    Struct.new(:targets).new(targets)
  end

  it "stops a plan that builds a gem for a target whose Ruby cannot load it, saying why it is built there" do
    expect { described_class.call(plan("bookworm/amd64" => :build, "trixie/amd64" => :build), release_catalog, resolution) }
      .to raise_error(Relspec::InvalidInput) do |error|
        expect(error.diagnostics.map { |diagnostic| [diagnostic.rule, diagnostic.message, diagnostic.location.to_s] })
          .to eq([["gem-ruby", "gem core 1.3.0 needs Ruby >= 3.2, and would be built for bookworm/amd64 (Ruby 3.1.2) " \
                               "(not taken from the distribution: ruby-web 1.6.2-3 (bookworm) depends on core, which the " \
                               "release packages at 1.3.0): it would install there but not load", "#{@dir}/specs/rel.yml:5:1"]])
      end
  end

  it "lets the distribution's package stand where the Ruby is older" do
    expect(described_class.call(plan("bookworm/amd64" => :system, "trixie/amd64" => :build), release_catalog, resolution)).to be_nil
  end
end
