# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/mirror/manifest"

RSpec.describe Relspec::Mirror::Manifest do
  around { |example| Dir.mktmpdir("relspec-manifest") { |dir| @dir = dir and example.run } }

  def target(text) = Relspec::Target.parse(text)

  def read(text)
    File.write(File.join(@dir, "mirror.yml"), text)
    described_class.read(@dir)
  end

  def refusal(text)
    read(text)
    raise "not refused"
  rescue Relspec::InvalidInput => e
    e.diagnostics.join("\n")
  end

  it "reads back what it writes, targets sorted" do
    manifest = described_class.new(release: "demo", key: "demo-mirror.asc",
                                   targets: { target("bookworm/arm64") => %w[bb], target("bookworm/amd64") => %w[aa cc] })
    manifest.write(@dir)
    again = described_class.read(@dir)
    expect([again.release, again.key, again.targets]).to eq(["demo", "demo-mirror.asc",
                                                             { target("bookworm/amd64") => %w[aa cc], target("bookworm/arm64") => %w[bb] }])
    expect(again.targets.keys.first).to be_frozen
    expect(again).to be_frozen
  end

  it "says a folder without mirror.yml is no mirror" do
    expect { described_class.read(@dir) }.to raise_error(Relspec::Mirror::NotAMirror, /has no mirror.yml/)
  end

  it "refuses a package name apt would read as an option, at its line, by the package set's name rule" do
    text = "release: demo\ntargets:\n  bookworm/amd64:\n    release:\n    - ok1\n    - \"-oDPkg::Pre-Invoke::=touch x\"\n"
    expect(refusal(text)).to eq("#{@dir}/mirror.yml:6:7: error[mirror-manifest]: cannot read mirror.yml: " \
                                "\"-oDPkg::Pre-Invoke::=touch x\" is not a Debian package name (lowercase letters, digits, " \
                                "+ - ., not starting with - or .)\n  hint: #{described_class::HINT}")
  end

  it "refuses a key that is not the release's key beside mirror.yml, a path as a target and unknown keys" do
    expect(refusal("release: demo\nkey: ../../etc/apt/trusted.gpg\ntargets: {bookworm/amd64: {release: []}}\n"))
      .to include("mirror.yml:2:6: error[mirror-manifest]", "the key \"../../etc/apt/trusted.gpg\" is not demo-mirror.asc")
    expect(refusal("release: demo\ntargets: {../../etc/amd64: {release: []}}\n"))
      .to include("mirror.yml:2:28:", "\"../../etc/amd64\" is not a target name")
    expect(refusal("release: demo\ntargets: {bookworm/amd64: {release: [], extra: 1}}\n")).to include("unknown key \"extra\"")
    expect(refusal("release: ../x\ntargets: {bookworm/amd64: {release: []}}\n")).to include("\"../x\" is not a release name")
    expect(refusal("release: demo\ntargets: {}\n")).to include("targets lists no target")
    expect(refusal("[1, 2]\n")).to include("the file is empty or not a mapping")
  end
end
