# frozen_string_literal: true

require "spec_helper"

RSpec.describe "repository.sign_with" do
  it "accepts sign_with in a spec's own repository only" do
    with_specs("own" => "release: own\ntargets: { bookworm: [amd64] }\nrepository: { path: /srv/own, keyring: k.gpg, sign_with: ABCD }\n",
               "ext" => "release: ext\nparent: x\nexternal: { x: { path: /srv/x, trusted: true, sign_with: ABCD } }\n") do |dir|
      expect(Relspec::ReleaseSpec::SpecFile.load(File.join(dir, "own.yml")).diagnostics).to be_empty
      messages = Relspec::ReleaseSpec::SpecFile.load(File.join(dir, "ext.yml")).diagnostics.map(&:to_s)
      expect(messages.join).to include("sign_with")
    end
  end
end
