# frozen_string_literal: true

require_relative "../unit_helper"

# BuildInput is the whole input of debian/: frozen, with what the
# presenters derive from it in one place.
RSpec.describe Relspec::Debian::BuildInput do
  it "is frozen, copies its lists, and names the prefixes of release-built dependencies only" do
    defines = { "A" => "1" }
    input = build_input(defines: defines, dependencies: [dependency("rock-r-a", "/opt/rock/r/rock-r-a"),
                                                         dependency("libfoo-dev", nil)])
    defines["B"] = "2"
    expect(input).to be_frozen
    expect(input.defines).to eq("A" => "1").and be_frozen
    expect(input.dependency_dirs).to eq(["/opt/rock/r/rock-r-a"])
    expect(input.extension_task).to be_nil
    expect(input.gem_file).to be_nil
  end

  it "takes a plain shell name other than the standard ones as a variable debian/rules carries" do
    expect(described_class.variable?("OROGEN_PLUGIN_PATH")).to be(true)
    expect(described_class.variable?("PATH")).to be(false)
    expect(described_class.variable?("A B")).to be(false)
    expect(described_class.variable?(nil)).to be(false)
  end
end
