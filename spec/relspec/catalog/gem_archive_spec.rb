# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/gem_archive"
require_relative "../../support/gem_builder"

# Which gems hand headers to other code (and so need Ruby's headers wherever
# they are used), on real .gem files.
RSpec.describe Relspec::Catalog::GemArchive, :tmpdir do
  def archive(name, **options)
    path = GemBuilder.build(@dir, name, "1.0.0", **options)
    described_class.new(name, "1.0.0", path, "test")
  end

  it "says a native gem with headers outside ext/ ships headers for other code (Rice's rice/*.hpp)" do
    expect(archive("cxxlib", extension: true, files: { "cxxlib/Object.hpp" => "#include <ruby.h>\n" }).ships_headers?)
      .to be(true)
  end

  it "does not say so for a native gem whose headers serve only its own extension, nor for a pure gem" do
    expect(archive("cext", extension: true, files: { "ext/cext/cext.h" => "int x;\n" }).ships_headers?).to be(false)
    expect(archive("pure", files: { "lib/pure/x.h" => "int x;\n" }).ships_headers?).to be(false)
  end

  it "gives the gemspec's required_ruby_version, >= 0 when it sets none" do
    expect(archive("modern", ruby: ">= 3.2").required_ruby).to eq(Gem::Requirement.new(">= 3.2"))
    expect(archive("any").required_ruby).to eq(Gem::Requirement.default)
  end
end
