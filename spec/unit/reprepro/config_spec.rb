# frozen_string_literal: true

require "spec_helper"
require "relspec/publish/repository_config"
require "relspec/plan/target"

RSpec.describe Relspec::Publish::RepositoryConfig do
  def targets(*names)
    names.map { |name| Relspec::Plan::Target.parse(name) }
  end

  it "has one distribution per codename with its architectures and source, signed when asked" do
    config = described_class.new(release: "demo", targets: targets("focal/arm64", "bookworm/amd64", "focal/amd64"),
                                 sign_with: "0123ABCD")
    expect(config.distributions).to eq(<<~CONF)
      Codename: bookworm
      Suite: bookworm
      Label: demo
      Architectures: amd64 source
      Components: main
      Description: demo for bookworm
      SignWith: 0123ABCD

      Codename: focal
      Suite: focal
      Label: demo
      Architectures: amd64 arm64 source
      Components: main
      Description: demo for focal
      SignWith: 0123ABCD
    CONF
    expect(config.options).to eq("waitforlock #{described_class::WAIT_FOR_LOCK}\n")
    expect(described_class.new(release: "demo", targets: targets("bookworm/amd64")).distributions).not_to include("SignWith")
  end

  it "accepts sign_with in a spec's own repository only" do
    with_specs("own" => "release: own\ntargets: { bookworm: [amd64] }\nrepository: { path: /srv/own, keyring: k.gpg, sign_with: ABCD }\n",
               "ext" => "release: ext\nparent: x\nexternal: { x: { path: /srv/x, trusted: true, sign_with: ABCD } }\n") do |dir|
      expect(Relspec::ReleaseSpec::SpecFile.load(File.join(dir, "own.yml")).diagnostics).to be_empty
      messages = Relspec::ReleaseSpec::SpecFile.load(File.join(dir, "ext.yml")).diagnostics.map(&:to_s)
      expect(messages.join).to include("sign_with")
    end
  end
end
