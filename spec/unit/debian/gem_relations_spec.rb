# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/gem_relations"

RSpec.describe Relspec::Debian::GemRelations do
  it "turns each bound of a gem constraint into a Debian relation" do
    expect(described_class.of("ruby-rice", "<4.0.0")).to eq(["ruby-rice (<< 4.0.0)"])
    expect(described_class.of("ruby-rice", ">= 3.0, < 4")).to eq(["ruby-rice (>= 3.0)", "ruby-rice (<< 4)"])
    expect(described_class.of("ruby-rice", "= 3.1.pre")).to eq(["ruby-rice (= 3.1~pre)"])
  end

  it "reads ~> as RubyGems does: at least the version, below the next bump" do
    expect(described_class.of("ruby-foo", "~> 1.2")).to eq(["ruby-foo (>= 1.2)", "ruby-foo (<< 2)"])
    expect(described_class.of("ruby-foo", "~> 1.2.3")).to eq(["ruby-foo (>= 1.2.3)", "ruby-foo (<< 1.3)"])
  end

  it "names the bare package when nothing can be said" do
    expect(described_class.of("ruby-foo", "")).to eq(["ruby-foo"])
    expect(described_class.of("ruby-foo", ">= 0")).to eq(["ruby-foo"])
    expect(described_class.of("ruby-foo", "!= 1.0")).to eq(["ruby-foo"])
    expect(described_class.of("ruby-foo", "<<< nonsense")).to eq(["ruby-foo"])
  end
end
