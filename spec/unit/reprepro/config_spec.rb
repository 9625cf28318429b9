# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/reprepro/config"
require "relspec/target"

# conf/ of a release's repository (publish) and of a field mirror: one
# distribution per codename, written only when it changes.
RSpec.describe Relspec::Reprepro::Config do
  def targets(*names)
    names.map { |name| Relspec::Target.parse(name) }
  end

  def release(sign_with: nil, names: ["focal/arm64", "bookworm/amd64", "focal/amd64"])
    described_class.new(label: "demo", description: "demo for %<codename>s", targets: targets(*names), source: true,
                        sign_with: sign_with)
  end

  it "has one distribution per codename with its architectures and source, signed when asked" do
    expect(release(sign_with: "0123ABCD").distributions).to eq(<<~CONF)
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
    expect(release.options).to eq("waitforlock #{described_class::WAIT_FOR_LOCK}\n")
    expect(release(names: ["bookworm/amd64"]).distributions).not_to include("SignWith")
  end

  it "leaves source out for a mirror's binaries" do
    mirror = described_class.new(label: "relspec mirror", description: "mirror from %<codename>s", targets: targets("bookworm/arm64"),
                                 source: false)
    expect(mirror.distributions).to include("Label: relspec mirror\nArchitectures: arm64\n", "Description: mirror from bookworm\n")
  end

  it "writes conf/ and says whether it changed" do
    Dir.mktmpdir do |dir|
      conf = File.join(dir, "conf")
      expect(release.write(conf)).to be(true)
      expect(release.write(conf)).to be(false)
      expect(File.read(File.join(conf, "options"))).to eq("waitforlock 30\n")
      expect(release(sign_with: "AB").write(conf)).to be(true)
      expect(File.read(File.join(conf, "distributions"))).to include("SignWith: AB")
    end
  end
end
