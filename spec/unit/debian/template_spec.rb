# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/template"

# Templates become methods of their presenter's Struct, compiled once.
RSpec.describe Relspec::Debian::Template do
  it "renders a template of templates/ with the variables given" do
    context = Struct.new(:source, :section, :maintainer, :build_depends, :depends, :homepage, :architecture,
                         :synopsis, :long_description, keyword_init: true)
    methods = described_class.compile(context, %w[control.erb])
    expect(methods).to eq("control.erb" => :render_control).and be_frozen
    text = described_class.render(context, methods, "control.erb",
                                  source: "s", section: "misc", maintainer: "M", build_depends: %w[a b], depends: ["c"],
                                  homepage: nil, architecture: "all", synopsis: "syn", long_description: " long")
    expect(text).to start_with("Source: s\nSection: misc\n").and include("Build-Depends: a,\n b\n")
    expect(text).not_to include("Homepage")
    expect { described_class.render(context, methods, "rules.erb", {}) }.to raise_error(KeyError)
  end
end
