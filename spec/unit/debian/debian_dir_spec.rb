# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/debian_dir"

# The whole debian/ of one package from its BuildInput: every file with its
# mode, and a digest that does not depend on the revision it decides.
RSpec.describe Relspec::Debian::DebianDir do
  it "renders every file of debian/, rules executable, debian/compat only for old debhelpers" do
    files = described_class.render(build_input, version: "0.1-1~bookworm")
    expect(files.keys).to eq(%w[control changelog copyright rules source/format env.sh env.yml relspec.yml
                                rock-r-pkg.lintian-overrides])
    expect(files.transform_values(&:last).select { |_, mode| mode == 0o755 }.keys).to eq(["rules"])
    expect(files["source/format"]).to eq(["3.0 (quilt)\n", 0o644])
    expect(files["changelog"].first).to start_with("rock-r-pkg (0.1-1~bookworm) bookworm;")
    expect(described_class.render(build_input(debhelper_compat: 9), version: nil)["compat"]).to eq(["9\n", 0o644])
  end

  it "digests debian/ without its version: the placeholder stands for it" do
    digest = ->(input) { described_class.digest(described_class.render(input, version: nil)) }
    expect(described_class.render(build_input, version: nil)["changelog"].first).to include("(@RELSPEC_VERSION@)")
    expect(digest.call(build_input)).to eq(digest.call(build_input))
    expect(digest.call(build_input(defines: { "A" => "1" }))).not_to eq(digest.call(build_input))
  end
end
