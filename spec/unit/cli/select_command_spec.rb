# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/cli/select_command"

# `relspec osdeps select`: Osdeps.select, then what it did and its warnings.
RSpec.describe Relspec::CLI::SelectCommand do
  it "says how many packages stay active and warns of a blacklist entry that matches nothing" do
    Dir.mktmpdir do |dir|
      File.write(File.join(dir, "releases.yml"), "r: ~\n")
      File.write(File.join(dir, "r-amd64.yml"), "base/x:\n  debian:\n    12,bookworm: rock-r-base-x\n")
      File.write(File.join(dir, "deb_blacklist.yml"), "- gui/none\n")
      err = StringIO.new
      described_class.new({ release: "r", arch: "amd64", os: "debian:12,bookworm", data: dir,
                            blacklist: File.join(dir, "deb_blacklist.yml"), index: [], trusted: false, keyring: nil,
                            output: File.join(dir, "out") }, err: err).call
      expect(err.string.lines.last).to eq("1 packages active, 0 disabled (#{File.join(dir, 'out', 'rock-osdeps.osdeps')})\n")
      expect(err.string).to include('warning[unmatched-blacklist]: "gui/none" matches no package of r')
    end
  end
end
