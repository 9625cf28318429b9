# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/cause"

# (a file of its own: main has spec/unit/plan/cause_spec.rb for the other causes)
RSpec.describe Relspec::Plan::Cause do
  it "says why autoproj's exclusions and osdeps of other systems make a package unavailable, down the chain" do
    excluded = described_class.excluded("USE_OCL is set to false")
    other_os = described_class.other_os_osdeps(["qtruby"], "bookworm")
    expect(excluded.to_s).to eq("excluded by autoproj: USE_OCL is set to false")
    expect(other_os.to_s).to eq("osdep qtruby is defined for other systems only, not bookworm")
    expect(described_class.other_os_osdeps(%w[a b], "bookworm").to_s).to start_with("osdeps a, b are defined")
    chain = described_class.unavailable_dependency("gui/vizkit", other_os)
    expect(chain.chain).to eq(["depends on gui/vizkit", "osdep qtruby is defined for other systems only, not bookworm"])
    expect(chain.root).to be(other_os)
  end
end
