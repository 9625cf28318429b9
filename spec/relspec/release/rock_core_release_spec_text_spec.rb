# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "yaml"
require_relative "../../support/rock_core_workspace"

# bin/rock-core-release's one spec for every target (issue 44, item 3): it
# is a spec relspec accepts, with one target per chosen codename/arch and
# each leave_out for the targets it concerns only.
RSpec.describe "the Rock core release's spec (bin/rock-core-release)" do
  def written(targets)
    Dir.mktmpdir("relspec-rock-core-spec") do |dir|
      release = targets ? RockCoreRelease.new(dir, targets: targets) : RockCoreRelease.new(dir)
      FileUtils.mkdir_p(File.dirname(release.spec_path))
      File.write(release.spec_path, release.spec_text)
      run = relspec("validate", release.spec_path)
      expect(run.exit_code).to eq(0), run.stderr
      YAML.safe_load_file(release.spec_path)
    end
  end

  it "targets bookworm/amd64 and trixie/amd64 by default, bookworm from this machine's apt, trixie from Debian's" do
    spec = written(nil)
    expect(spec["targets"]).to eq("bookworm" => ["amd64"], "trixie" => ["amd64"])
    expect(spec["distributions"]).to eq(
      "bookworm" => { "archive" => { "host" => true } },
      "trixie" => { "archive" => { "url" => "http://deb.debian.org/debian",
                                   "keyring" => "/usr/share/keyrings/debian-archive-keyring.gpg" } }
    )
    expect(spec["leave_out"].map { |entry| entry["targets"] }.uniq).to eq([%w[bookworm trixie]])
  end

  it "writes only the targets --targets chooses, and leave_out for those only" do
    spec = written(%w[trixie/amd64])
    expect(spec["targets"]).to eq("trixie" => ["amd64"])
    expect(spec["distributions"].keys).to eq(%w[trixie])
    expect(spec["leave_out"].map { |entry| entry["match"] }).to include("gui/vizkit", "gui/vizkit3d")
    expect(spec["leave_out"].map { |entry| entry["targets"] }.uniq).to eq([%w[trixie]])
  end
end
