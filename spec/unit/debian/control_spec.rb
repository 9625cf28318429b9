# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/debian/control"

# debian/control and the lintian overrides of one package.
RSpec.describe Relspec::Debian::Control do
  def control(input) = described_class.new(input)

  it "names the package, its relations and its section" do
    input = build_input(dependencies: [dependency("rock-r-a", "/opt/rock/r/rock-r-a")], apt: ["libfoo-dev"],
                        package: { summary: "Does things.", description: "Does things.\n\n  More text." })
    text = control(input).control
    expect(text).to include("Source: rock-r-pkg\nSection: devel\n", "Homepage: https://example.org/pkg\n",
                            "Package: rock-r-pkg\nArchitecture: any\n", "Description: Does things\n More text.\n .\n")
    expect(text[/^Build-Depends:(.*?)^(?=\S)/m, 1]).to include("rock-r-a (>= 1.0-1)", "libfoo-dev", "debhelper-compat (= 13)")
  end

  it "is architecture-independent for Ruby code, dependent when it compiles an extension" do
    expect(control(build_input(build_type: "ruby")).architecture).to eq("all")
    expect(control(build_input(build_type: "ruby", extension_task: "default")).architecture).to eq("any")
    expect(control(build_input(build_type: "ruby", extension_task: "default")).control[/^Build-Depends:(.*?)^(?=\S)/m, 1])
      .to include("ruby-dev")
    expect(control(build_input(build_type: "meta")).control).not_to include("Homepage")
  end

  it "overrides lintian for every folder of the prefix under /opt, and the RUNPATH of compiled code" do
    expect(control(build_input).lintian_overrides).to eq(<<~TEXT)
      # packages of a release live in /opt by design
      rock-r-pkg: dir-or-file-in-opt [opt/rock/]
      rock-r-pkg: dir-or-file-in-opt [opt/rock/r/]
      rock-r-pkg: dir-or-file-in-opt [opt/rock/r/rock-r-pkg/*]
      # libraries of the release are found through RUNPATH into its prefixes under /opt
      rock-r-pkg: custom-library-search-path
    TEXT
    expect(control(build_input(build_type: "import")).lintian_overrides).not_to include("custom-library-search-path")
  end
end
