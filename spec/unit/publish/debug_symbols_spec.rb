# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/debug_symbols"

# Which built files are debug-symbol packages, by dpkg's file names only.
RSpec.describe Relspec::Publish::DebugSymbols do
  let(:built) do
    %w[results/rock-demo-base-logging/rock-demo-base-logging_0.1-1_amd64.deb
       results/rock-demo-base-logging/rock-demo-base-logging-dbgsym_0.1-1_amd64.deb
       results/rock-demo-dbgsym-tools/rock-demo-dbgsym-tools_1.0_all.deb]
  end

  it "knows the -dbgsym .deb and .ddeb of any package, and nothing that only looks like one" do
    expect(described_class.package?("/out/libfoo-dbgsym_1:2.0-1_arm64.deb")).to be(true)
    expect(described_class.package?("libfoo-dbgsym_2.0_amd64.ddeb")).to be(true)
    # a package whose name holds "dbgsym", a source package, a name without version and arch
    expect(described_class.package?("rock-demo-dbgsym-tools_1.0_all.deb")).to be(false)
    expect(described_class.package?("libfoo-dbgsym_2.0.dsc")).to be(false)
    expect(described_class.package?("libfoo-dbgsym.deb")).to be(false)
    expect(described_class.package?("libfoo-dbgsym_2.0_amd64.deb/other.deb")).to be(false)
  end

  it "leaves the debug-symbol packages out unless they are asked for" do
    expect(described_class.select(built, included: false)).to eq(built.values_at(0, 2))
    expect(described_class.select(built, included: true)).to eq(built)
  end
end
