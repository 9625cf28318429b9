# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/osdeps/release_data"
require "relspec/osdeps/operating_system"

# `osdeps select`'s reading of a data folder, through Osdeps::Reader.
RSpec.describe Relspec::Osdeps::ReleaseData, :tmpdir do
  let(:bionic) { Relspec::Osdeps::OperatingSystem.new(%w[ubuntu debian], %w[18.04 bionic]) }

  def write(name, text)
    File.write(File.join(@dir, name), text)
  end

  def entry(deb)
    "  ubuntu,debian:\n    18.04,bionic: #{deb}\n"
  end

  it "resolves the release over its ancestors, an ancestor's missing file being nothing" do
    write("releases.yml", "default: { repo_url: http://h }\nroot: ~\nbase: { depends_on: root }\nrel: { depends_on: base }\n")
    write("base-amd64.yml", "a:\n#{entry('rock-base-a')}b:\n#{entry('rock-base-b')}")
    write("rel-amd64.yml", "a:\n#{entry('rock-rel-a')}gem:\n  gem: not_a_debian_name\n")
    data = described_class.new(@dir)
    expect(data.lineage("rel")).to eq(%w[root base rel])
    expect(data.resolved("rel", "amd64", bionic)).to eq("a" => "rock-rel-a", "b" => "rock-base-b")
  end

  def problem(&block)
    block.call
    nil
  rescue Relspec::InvalidInput => e
    e.diagnostics.join("\n")
  end

  it "refuses the release's missing file, a name that is not a Debian one and a bad index, naming the file" do
    write("releases.yml", "rel: ~\n")
    expect(problem { described_class.new(@dir).resolved("rel", "amd64", bionic) }).to include("error[missing-osdeps]: no osdeps file")
    write("rel-amd64.yml", "a:\n#{entry('"-oX=y"')}")
    expect(problem { described_class.new(@dir).resolved("rel", "amd64", bionic) })
      .to include("rel-amd64.yml: error[osdeps-file]: a: \"-oX=y\" is not a Debian package name")
    write("releases.yml", "rel: { depends_on: gone }\n")
    expect(problem { described_class.new(@dir).lineage("rel") })
      .to include("releases.yml: error[release-index]: rel depends on gone, which it does not hold")
    write("releases.yml", "rel: 1\nrel: 2\n")
    expect(problem { described_class.new(@dir).lineage("rel") }).to include("releases.yml:2:")
  end
end
