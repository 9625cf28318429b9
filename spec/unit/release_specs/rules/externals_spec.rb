# frozen_string_literal: true

require_relative "../../unit_helper"
require "relspec/release_specs/rules/externals"

RSpec.describe Relspec::ReleaseSpec::Rules::Externals do
  def check(text)
    findings(described_class.call(spec_file("release: child\nexternal:\n#{text}")))
  end

  it "accepts an external release with a repository, targets and a prefix" do
    expect(check("  rock-old:\n    url: https://example.org/old\n    trusted: true\n    targets: { bionic: [amd64] }\n    " \
                 "package_prefix: rock-old\n")).to eq([])
  end

  it "checks the name, the repository, the targets and the prefix with the same rules as a spec's own" do
    expect(check("  Old_One:\n    keyring: k.gpg\n    targets: { bionic: [] }\n    package_prefix: Old\n")).to eq([
      'error release-name@3: invalid external release name "Old_One"',
      "error repository-location@4: external release Old_One has neither path nor url",
      "error empty-targets@5: bionic lists no architecture",
      'error package-prefix@6: package prefix "Old" cannot start a Debian package name'
    ])
  end
end
