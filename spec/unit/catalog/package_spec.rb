# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/package"

RSpec.describe Relspec::Catalog::Package do
  let(:patch) { { "path" => "set/patches/fix.patch", "level" => 1, "content" => "--- a/x\n+++ b/x\n" } }

  it "carries the package set's import patches through to_h and from_h, in order" do
    hash = { "package_set" => "set", "build_type" => "cmake", "vcs" => { "type" => "git", "url" => "u" },
             "source_dir" => "src/x", "patches" => [patch, patch.merge("path" => "set/patches/a.patch")] }
    package = described_class.from_h("x", hash)
    expect(package.patches.map(&:path)).to eq(%w[set/patches/fix.patch set/patches/a.patch])
    expect(package.patches).to all(be_frozen)
    expect(package.to_h).to eq(hash)
    expect(described_class.from_h("x", hash.except("patches")).to_h).not_to have_key("patches")
  end
end
