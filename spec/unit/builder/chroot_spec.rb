# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/chroot"
require "relspec/target"
require "relspec/release_specs/values/archive"

# The chroot tarball's mmdebstrap command, as a Slurm prepare job runs it
# (Chroot#job_steps), with the mirror from the spec: nothing is run.
RSpec.describe Relspec::Builder::Chroot do
  let(:distribution) do
    Struct.new(:archive).new(Relspec::ReleaseSpec::Archive.from({ "url" => "http://deb.example.org/debian" }))
  end

  it "keeps apt's lists in the tarball and lets dpkg skip fsync in the throw-away chroot" do
    Dir.mktmpdir do |cache|
      target = Relspec::Target.new("bookworm", "amd64")
      chroot = described_class.new(target, distribution, nil, cache_dir: cache, emulation: nil)
      step = chroot.job_steps.first
      expect(step).to include("mmdebstrap --variant=buildd --mode=unshare --arch=amd64 --include=debhelper,ccache,fakeroot " \
                              "--skip=cleanup/apt/lists --dpkgopt=force-unsafe-io " \
                              "--chrooted-customize-hook=update-ccache-symlinks bookworm ")
      expect(step).to include(" http://deb.example.org/debian && mv ")
      expect(chroot.path).to eq(File.join(cache, "bookworm-amd64.tar.zst"))
    end
  end

  # A machine with a relspec release installed through the package set has
  # its source in sources.list.d: a release repository is not the
  # distribution, and a chroot made with it would depend on that server.
  it "takes this machine's sources of the distribution, not those relspec's package set wrote" do
    Dir.mktmpdir do |etc|
      FileUtils.mkdir_p(File.join(etc, "sources.list.d"))
      File.write(File.join(etc, "sources.list"), "")
      File.write(File.join(etc, "sources.list.d", "debian.sources"), "Types: deb\nURIs: http://deb.debian.org/debian\n")
      File.write(File.join(etc, "sources.list.d", "relspec-demo-base.list"),
                 "# written by relspec's autoproj package set\ndeb [trusted=yes] http://127.0.0.1:8000/demo-base bookworm main\n")
      File.write(File.join(etc, "sources.list.d", "other.list"), "deb http://example.org/x bookworm main\n")
      expect(described_class.host_sources(etc)).to eq(%w[debian.sources other.list].map { |name| File.join(etc, "sources.list.d", name) })
    end
  end
end
