# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog"
require "relspec/catalog/package"
require "relspec/catalog/gem_resolution"
require "relspec/catalog/release_gems"
require "relspec/catalog/gem_depends"

# Gem osdeps resolved against a distribution's archive, in memory. The gem
# source stands for GemVersions with its two calls (what it lists, and
# where); it lists nothing, so a gem the distribution cannot provide is an
# error here.
RSpec.describe Relspec::Catalog::GemResolution do
  let(:catalog) do
    package = Relspec::Catalog::Package.new(
      name: "app", package_set: "set", build_type: "ruby", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/app",
      os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: ["minitest<5.16"]) },
      vcs: Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/app.git", commit: "c" * 40)
    )
    Relspec::Catalog.new(packages: { "app" => package }, layout: ["app"], codenames: ["bookworm"])
  end
  let(:no_gems) do
    Struct.new(:where) do
      def of(_name) = []
      def folder? = false
    end.new("gem_source")
  end

  def resolve(archive)
    described_class.new(catalog: catalog, selected: { "bookworm" => ["app"] }, pinned: {},
                        archives: { "bookworm/amd64" => archive }, locked: {}, versions: no_gems,
                        fetch: ->(*) { raise "nothing is fetched" }, blacklisted: ->(_) { false }, location: nil).call
  end

  # bookworm: ruby-minitest 5.17.0-1, and libruby3.1's Provides: ruby-minitest (= 5.15.0)
  it "takes a gem from the distribution when any version the archive has fits, not only the newest" do
    expect(resolve("ruby-minitest" => %w[5.17.0-1 5.15.0]).automatic).to eq({})
    expect { resolve("ruby-minitest" => %w[5.17.0-1]) }
      .to raise_error(Relspec::InvalidInput) { |error| expect(error.diagnostics.first.message).to include("no version of gem minitest") }
  end

  # trixie: ruby-dry-types 1.2.2 depends on ruby-dry-core, which the release packages (Debian's 0.7.1 is too old)
  describe "a distribution gem that depends on a gem packaged here" do
    let(:archives) do
      { "dry-types" => { "1.2.2" => {}, "1.9.1" => { "dry-core" => "~> 1.0" } }, "dry-core" => { "1.2.0" => {} } }
    end
    # "name version" => required_ruby_version of the .gem, and what the compact index says of it
    let(:rubies) { {} }
    let(:hints) { {} }
    let(:fetched) { [] }
    let(:versions) do
      listed = archives.transform_values { |found| found.keys.reverse.map { |version| Gem::Version.new(version) } }
      Struct.new(:listed, :where, :hints) do
        def of(name) = listed.fetch(name, [])
        def folder? = false
        def required_ruby(name, version) = hints["#{name} #{version}"]&.then { |text| Gem::Requirement.new(text) }
      end.new(listed, "gem_source", hints)
    end
    let(:fetch) do
      lambda do |name, version|
        fetched << "#{name} #{version}"
        Struct.new(:name, :version, :runtime_dependencies, :required_ruby)
              .new(name, version, archives.fetch(name).fetch(version).map { |gem, text| [gem, Gem::Requirement.new(text)] },
                   Gem::Requirement.new(rubies.fetch("#{name} #{version}", ">= 0")))
      end
    end

    def app_needing(*gems)
      package = catalog.package("app").with(os_dependencies: { "bookworm" => Relspec::Catalog::OsDependencies.build(gems: gems) })
      Relspec::Catalog.new(packages: { "app" => package }, layout: ["app"], codenames: ["bookworm"])
    end

    def resolve_with(depends, archive, target_rubies: Relspec::Catalog::TargetRubies::NONE, locked: {}, pinned: {}, others: {},
                     blacklisted: [])
      described_class.new(catalog: app_needing("dry-types>= 1.1", "dry-core>= 1.0"), selected: { "bookworm" => ["app"] },
                          pinned: pinned, archives: -> { { "bookworm/amd64" => archive }.merge(others) }, locked: locked,
                          versions: versions,
                          fetch: fetch, blacklisted: ->(name) { blacklisted.include?(name) }, location: nil,
                          depends: -> { { "bookworm/amd64" => depends } }, rubies: target_rubies,
                          locate: ->(_name) { Relspec::Location.new(file: "specs/app.yml", line: 4) }).call
    end

    let(:archive) { { "ruby-dry-types" => %w[1.2.2-2], "ruby-dry-core" => %w[0.7.1-1] } }

    it "packages it too, at the highest version that fits, and says why" do
      types = Relspec::Catalog::GemDepends.new(name: "ruby-dry-types", version: "1.2.2-2", depends: ["ruby-dry-core"])
      result = resolve_with({ "ruby-dry-types" => types }, archive)
      expect(result.automatic).to eq("dry-core" => "1.2.0", "dry-types" => "1.9.1")
      expect(result.notes).to eq(["ruby-dry-types 1.2.2-2 (bookworm) depends on dry-core, which the release packages at " \
                                  "1.2.0: gem dry-types is packaged here"])
      # without Debian's Depends it is the distribution's, as before
      expect(resolve_with({}, archive).automatic).to eq("dry-core" => "1.2.0")
    end

    it "names the shadowing when no version of it can be had" do
      archives.delete("dry-types")
      types = Relspec::Catalog::GemDepends.new(name: "ruby-dry-types", version: "1.2.2-2", depends: ["ruby-dry-core"])
      expect { resolve_with({ "ruby-dry-types" => types }, archive) }.to raise_error(Relspec::InvalidInput) do |error|
        expect(error.diagnostics.map(&:message))
          .to eq(["no version of gem dry-types in gem_source fits what is asked: app's osdep dry-types>= 1.1 (>= 1.1); " \
                  "it has none (not taken from the distribution: ruby-dry-types 1.2.2-2 (bookworm) depends on dry-core, " \
                  "which the release packages at 1.2.0)"])
      end
    end

    # dry-core 1.2.0 needs Ruby >= 3.2: on bookworm (3.1) it installs but does not load
    describe "the targets' Ruby" do
      let(:archives) do
        { "dry-types" => { "1.8.3" => { "dry-core" => "~> 1.0" }, "1.9.1" => { "dry-core" => "~> 1.1" } },
          "dry-core" => { "1.0.0" => {}, "1.1.0" => {}, "1.2.0" => {} } }
      end
      let(:bookworm) { Relspec::Catalog::TargetRubies.new("bookworm" => "3.1", "trixie" => "3.3") }

      before do
        rubies.merge!("dry-core 1.2.0" => ">= 3.2", "dry-types 1.9.1" => ">= 3.2", "dry-core 1.1.0" => ">= 3.1.0")
      end

      it "packages the highest version every target's Ruby runs, and the gems it needs at versions that fit too" do
        expect(resolve_with({}, {}).automatic).to eq("dry-core" => "1.2.0", "dry-types" => "1.9.1")
        expect(resolve_with({}, {}, target_rubies: bookworm).automatic).to eq("dry-core" => "1.1.0", "dry-types" => "1.8.3")
      end

      it "takes the compact index's word to skip a version without downloading it, and the .gem's over it" do
        hints.merge!("dry-core 1.2.0" => ">= 3.2", "dry-core 1.1.0" => ">= 3.4")
        expect(resolve_with({}, {}, target_rubies: bookworm).automatic).to include("dry-core" => "1.0.0")
        expect(fetched).not_to include("dry-core 1.2.0", "dry-core 1.1.0")
        fetched.clear
        hints.replace("dry-core 1.2.0" => ">= 2.0")
        expect(resolve_with({}, {}, target_rubies: bookworm).automatic).to include("dry-core" => "1.1.0")
        expect(fetched).to include("dry-core 1.2.0", "dry-core 1.1.0")
      end

      it "keeps the lock's version only while every target's Ruby runs it" do
        result = resolve_with({}, {}, target_rubies: bookworm, locked: { "dry-core" => "1.2.0", "dry-types" => "1.8.3" })
        expect(result.automatic).to eq("dry-core" => "1.1.0", "dry-types" => "1.8.3")
      end

      it "names the gem, the targets, their Ruby and what each version needs when none runs there" do
        rubies.merge!("dry-core 1.1.0" => ">= 3.2", "dry-core 1.0.0" => ">= 3.2")
        expect { resolve_with({}, {}, target_rubies: bookworm) }.to raise_error(Relspec::InvalidInput) do |error|
          expect(error.diagnostics.map(&:rule).uniq).to eq(["gem-ruby"])
          expect(error.diagnostics.first.message)
            .to start_with("no version of gem dry-core in gem_source that fits what is asked (app's osdep dry-core>= 1.0 (>= 1.0)")
            .and end_with(") runs on Ruby 3.1 (bookworm): 1.2.0 needs Ruby >= 3.2, 1.1.0 needs Ruby >= 3.2, 1.0.0 needs Ruby >= 3.2")
        end
      end

      it "takes the distribution's package on a target whose Ruby runs no version, and packages one for the others" do
        rubies.merge!("dry-core 1.1.0" => ">= 3.2", "dry-core 1.0.0" => ">= 3.2")
        result = resolve_with({}, { "ruby-dry-core" => %w[1.0.1-1] }, target_rubies: bookworm, others: { "trixie/amd64" => {} })
        expect(result.automatic).to eq("dry-core" => "1.2.0", "dry-types" => "1.8.3")
        expect(result.notes).to eq(["no version of gem dry-core that fits runs on the Ruby of bookworm: taken from the " \
                                    "distribution there, packaged at 1.2.0 for the other targets"])
        # a blacklisted gem is never taken from the distribution, nor is bookworm's 0.7.1, which does not fit
        expect do
          resolve_with({}, { "ruby-dry-core" => %w[1.0.1-1] }, target_rubies: bookworm, others: { "trixie/amd64" => {} },
                                                               blacklisted: ["dry-core"])
        end.to raise_error(Relspec::InvalidInput, /gem-ruby/)
        expect { resolve_with({}, { "ruby-dry-core" => %w[0.7.1-1] }, target_rubies: bookworm, others: { "trixie/amd64" => {} }) }
          .to raise_error(Relspec::InvalidInput, /gem-ruby/)
      end

      it "refuses a version of gems: whose Ruby a target lacks, at its entry, unless that distribution has it" do
        expect { resolve_with({}, {}, target_rubies: bookworm, pinned: { "dry-core" => "1.2.0" }) }
          .to raise_error(Relspec::InvalidInput) do |error|
            expect(error.diagnostics.map { |diagnostic| [diagnostic.rule, diagnostic.message, diagnostic.location.to_s] })
              .to eq([["gem-ruby", "gem dry-core 1.2.0 of gems: needs Ruby >= 3.2, which Ruby 3.1 (bookworm) is not: it " \
                                   "would install there but not load", "specs/app.yml:4:"]])
          end
        archive = { "ruby-dry-core" => %w[1.2.0-1] }
        expect(resolve_with({}, archive, target_rubies: Relspec::Catalog::TargetRubies.new("bookworm" => "3.1"),
                                         pinned: { "dry-core" => "1.2.0" }).provided).to eq(["dry-core"])
      end
    end
  end
end
