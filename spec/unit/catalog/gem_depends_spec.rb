# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/gem_depends"

RSpec.describe Relspec::Catalog::GemDepends do
  it "is frozen all the way down, the caller's own values left as they are" do
    names = %w[ruby-dry-core]
    depends = described_class.new(name: +"ruby-dry-types", version: +"1.2.2-2", depends: names)
    expect(depends).to be_frozen
    expect([depends.name, depends.version, depends.depends]).to all(be_frozen)
    expect(names).not_to be_frozen
    expect(depends.to_h).to eq(name: "ruby-dry-types", version: "1.2.2-2", depends: ["ruby-dry-core"])
  end
end
