# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_problems"

RSpec.describe Relspec::Catalog::GemProblems do
  let(:versions) do
    Struct.new(:listed, :where, :folder) do
      def of(_name) = listed
      def folder? = folder
    end.new(%w[1.2.0 1.1.0].map { |version| Gem::Version.new(version) }, "https://rubygems.org/info/<name>", false)
  end
  let(:asked) { [[Gem::Requirement.new(">= 1.0"), "app's osdep dry-core>= 1.0"], [Gem::Requirement.new("~> 1.0"), "gem dry-types 1.8.3"]] }

  it "names the gem, what asks for it, the targets whose Ruby no version runs on and what each needs" do
    rubies = Relspec::Catalog::TargetRubies.new("bookworm" => "3.1", "trixie" => "3.3", "jammy" => "3.0")
    refused = [["1.2.0", Gem::Requirement.new(">= 3.2")], ["1.1.0", Gem::Requirement.new(">= 3.1")],
               ["1.0.1", Gem::Requirement.new(">= 3.1")], ["1.0.0", Gem::Requirement.new(">= 3.1")]]
    problem = described_class.ruby_refused("dry-core", asked, versions, refused, rubies, location: nil)
    expect([problem.rule, problem.message])
      .to eq(["gem-ruby", "no version of gem dry-core in https://rubygems.org/info/<name> that fits what is asked (app's " \
                          "osdep dry-core>= 1.0 (>= 1.0), gem dry-types 1.8.3 (~> 1.0)) runs on Ruby 3.1 (bookworm), " \
                          "Ruby 3.0 (jammy): 1.2.0 needs Ruby >= 3.2, 1.1.0 needs Ruby >= 3.1, 1.0.1 needs Ruby >= 3.1, …"])
  end

  it "says what gem_source has when no version fits what is asked, and how to fill a folder" do
    problem = described_class.unresolvable("dry-core", asked, versions, shadowing: nil, location: nil)
    expect(problem.message).to eq("no version of gem dry-core in https://rubygems.org/info/<name> fits what is asked: app's " \
                                  "osdep dry-core>= 1.0 (>= 1.0), gem dry-types 1.8.3 (~> 1.0); it has 1.2.0, 1.1.0")
    versions.folder = true
    expect(described_class.unresolvable("dry-core", asked, versions, shadowing: nil, location: nil).hint)
      .to include("`gem fetch dry-core -v '>= 1.0, ~> 1.0'`")
  end
end
