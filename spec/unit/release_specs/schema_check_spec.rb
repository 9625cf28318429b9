# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/release_specs/schema_check"

# The schemas over a located document: each wrong value named with its
# file:line:column.
RSpec.describe Relspec::ReleaseSpec::SchemaCheck do
  def messages(text, name: "child")
    described_class.call(spec_file(text, name: name)).diagnostics.map(&:to_s)
  end

  it "accepts debug_symbols in the release's own repository, true or false" do
    expect(messages("release: child\nrepository: { path: repo, trusted: true, debug_symbols: true }\n")).to eq([])
    expect(messages("release: child\nrepository: { path: repo, trusted: true, debug_symbols: false }\n")).to eq([])
  end

  it "refuses a debug_symbols that is not a boolean, at its value" do
    expect(messages("release: child\nrepository:\n  path: repo\n  debug_symbols: \"yes\"\n"))
      .to eq(['specs/child.yml:4:18: error[wrong-type]: "debug_symbols" must be true or false, found a string'])
  end

  it "refuses debug_symbols in an external release's entry: only the own repository is published" do
    expect(messages("release: child\nparent: p\nexternal:\n  p: { path: /srv/p, trusted: true, debug_symbols: true }\n").first)
      .to start_with('specs/child.yml:4:37: error[unknown-key]: unknown key "debug_symbols"')
  end
end
