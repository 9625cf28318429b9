# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/chroot"
require "relspec/target"

# The chroot tarball's mmdebstrap command, as a Slurm prepare job runs it
# (Chroot#job_steps), with the mirror from the spec: nothing is run.
RSpec.describe Relspec::Builder::Chroot do
  let(:distribution) { Struct.new(:archive).new({ "url" => "http://deb.example.org/debian" }) }

  it "keeps apt's lists in the tarball and lets dpkg skip fsync in the throw-away chroot" do
    Dir.mktmpdir do |cache|
      target = Relspec::Target.new("bookworm", "amd64")
      chroot = described_class.new(target, distribution, nil, cache_dir: cache, emulation: nil)
      step = chroot.job_steps.first
      expect(step).to include("mmdebstrap --variant=buildd --mode=unshare --arch=amd64 --include=debhelper " \
                              "--skip=cleanup/apt/lists --dpkgopt=force-unsafe-io bookworm ")
      expect(step).to include(" http://deb.example.org/debian && mv ")
      expect(chroot.path).to eq(File.join(cache, "bookworm-amd64.tar.zst"))
    end
  end
end
