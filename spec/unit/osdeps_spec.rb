# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/osdeps"

# The `relspec osdeps …` use cases, on spec files and data folders (render
# plans, and package-set reads published repositories: their scenario specs
# are spec/relspec/osdeps/render_spec.rb and spec/hostile/package_set_spec.rb).
RSpec.describe Relspec::Osdeps, :tmpdir do
  def spec(name, text)
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "#{name}.yml"),
               "release: #{name}\ntargets: { bookworm: [amd64] }\nrepository: { url: https://example.org/r/#{name} }\n#{text}")
  end

  it "writes releases.yml beside specs/, only when it changes" do
    spec("a", "")
    spec("b", "parent: a\n")
    specs = File.join(@dir, "specs")
    written = described_class.index(specs: specs)
    expect([written.path, written.changed]).to eq([File.join(@dir, "releases", "releases.yml"), true])
    expect(YAML.safe_load(File.read(written.path))).to include("b" => { "depends_on" => "a" })
    expect(described_class.index(specs: specs).changed).to be(false)
  end

  it "refuses a --repo-url that is not http(s) and a folder without specs, writing nothing" do
    spec("a", "")
    expect { described_class.index(specs: File.join(@dir, "specs"), repo_url: "file:///srv") }
      .to raise_error(Relspec::InvalidOption, '--repo-url must be an http(s) URL, not "file:///srv"')
    FileUtils.mkdir_p(File.join(@dir, "empty"))
    expect { described_class.package_set(specs: File.join(@dir, "empty"), out: File.join(@dir, "set")) }
      .to raise_error(Relspec::InvalidOption, "#{File.join(@dir, 'empty')}/ holds no release spec")
    expect(Dir.exist?(File.join(@dir, "releases")) || Dir.exist?(File.join(@dir, "set"))).to be(false)
  end

  it "selects a user's packages from a data folder" do
    data = File.join(@dir, "data")
    FileUtils.mkdir_p(data)
    File.write(File.join(data, "releases.yml"), "r: ~\n")
    File.write(File.join(data, "r-amd64.yml"), "base/x:\n  debian:\n    12,bookworm: rock-r-base-x\n")
    result = described_class.select(release: "r", arch: "amd64", os: "debian:12,bookworm", data: data, blacklist: nil,
                                    index: [], trusted: false, keyring: nil, output: File.join(@dir, "out"))
    expect(result.selection.active).to eq("base/x" => "rock-r-base-x")
    expect(File.read(result.path)).to include("rock-r-base-x")
  end
end
