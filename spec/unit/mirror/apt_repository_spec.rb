# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/mirror/apt_repository"

# configure and held_targets only (no reprepro runs): the mirror's own
# conf/distributions names the targets it holds, and a run that leaves one
# of them out is refused before conf/ is written.
RSpec.describe Relspec::Mirror::AptRepository do
  around do |example|
    Dir.mktmpdir("relspec-unit-mirror-repository") do |dir|
      @dir = File.join(dir, "mirror")
      example.run
    end
  end

  let(:bookworm) { Relspec::Target.new("bookworm", "amd64") }
  let(:trixie) { Relspec::Target.new("trixie", "amd64") }
  let(:trixie_arm) { Relspec::Target.new("trixie", "arm64") }

  it "holds no target before its first run, then every target it was configured with" do
    repository = described_class.new(@dir, targets: [bookworm, trixie, trixie_arm])
    expect(repository.held_targets).to eq([])
    repository.configure
    expect(repository.held_targets).to contain_exactly(bookworm, trixie, trixie_arm)
  end

  it "refuses a run that leaves out a target the mirror holds, before conf/ changes" do
    described_class.new(@dir, targets: [bookworm, trixie]).configure
    conf = File.read(File.join(@dir, "conf", "distributions"))

    expect { described_class.new(@dir, targets: [trixie]).configure(left_out: [bookworm]) }
      .to raise_error(Relspec::InvalidOption, %r{holds bookworm/amd64 too: a run for trixie/amd64 alone would remove it})
    expect(File.read(File.join(@dir, "conf", "distributions"))).to eq(conf)
  end

  it "takes a run for some targets when the others are not in the mirror" do
    described_class.new(@dir, targets: [trixie]).configure
    expect { described_class.new(@dir, targets: [trixie]).configure(left_out: [bookworm]) }.not_to raise_error
    expect(described_class.new(@dir, targets: [bookworm]).tap { |repository| repository.configure(left_out: []) }
                          .held_targets).to eq([bookworm])
  end
end
