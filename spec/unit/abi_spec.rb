# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/abi"

# Where the ABI report looks for published dumps: the releases of the
# lineage that publish somewhere, own release first. Specs are written to a temporary folder and
# resolved as relspec reads them; nothing is fetched.
RSpec.describe Relspec::Abi, :tmpdir do
  before do
    File.write(File.join(@dir, "base.yml"), <<~YAML)
      release: base
      workspace: ws
      targets: { bookworm: [amd64] }
      repository: { path: repos/base, url: http://127.0.0.1:1/base, trusted: true }
      parent: far
      external:
        far: { url: http://127.0.0.1:1/far, trusted: true }
    YAML
    File.write(File.join(@dir, "child.yml"), "release: child\nparent: base\nworkspace: ws\n")
  end

  def publishers(name)
    described_class.published_by(Relspec::ReleaseSpec.resolve(File.join(@dir, "#{name}.yml")).lineage)
  end

  it "lists the lineage's releases that have a repository, own first, with where it is" do
    expect(publishers("base").map { |publisher| [publisher.name, publisher.uri.to_s] })
      .to eq([["base", "http://127.0.0.1:1/base"], ["far", "http://127.0.0.1:1/far"]])
    expect(publishers("child").map(&:name)).to eq(%w[base far])
    expect(publishers("base")).to all(be_frozen)
  end
end
