# frozen_string_literal: true

require "spec_helper"
require "relspec/builder"
require_relative "../../support/build_release"

# A foreign architecture's chroot needs qemu-user-static, its binfmt_misc
# entry and arch-test. The variants are checked against a folder laid out
# as /usr/bin and /proc/sys/fs/binfmt_misc (no test may register emulators
# on this machine); the CLI case runs on this machine as it is.
RSpec.describe Relspec::Builder::Emulation, :tmpdir do
  def lay_out(*files)
    files.each do |file, content|
      FileUtils.mkdir_p(File.dirname(File.join(@dir, file)))
      File.write(File.join(@dir, file), content || "")
    end
  end

  it "needs nothing for the host's own architecture and the ones its processor runs" do
    emulation = described_class.new("amd64", root: @dir)
    expect(emulation.needed?("i386")).to be(false)
    expect { emulation.check("amd64") }.not_to raise_error
    expect(emulation.needed?("arm64")).to be(true)
  end

  it "names every missing piece and how to set it up" do
    expect { described_class.new("amd64", root: @dir).check("arm64") }.to raise_error(
      Relspec::BuildError,
      "cannot build arm64 on this amd64 machine: no emulator (/usr/bin/qemu-aarch64-static: qemu-user-static); " \
      "binfmt_misc is not mounted (/proc/sys/fs/binfmt_misc); no arch-test (/usr/bin/arch-test, which mmdebstrap " \
      "needs for a foreign architecture). To build by emulation: apt-get install qemu-user-static binfmt-support " \
      "arch-test (this registers emulators machine-wide), or build on arm64 nodes (docs/scale-out.md)"
    )
    lay_out(["usr/bin/qemu-arm-static"], ["usr/bin/arch-test"], ["proc/sys/fs/binfmt_misc/status", "enabled\n"],
            ["proc/sys/fs/binfmt_misc/qemu-arm", "disabled\n"])
    expect { described_class.new("amd64", root: @dir).check("armhf") }
      .to raise_error(Relspec::BuildError, /: no enabled binfmt_misc entry qemu-arm \(binfmt-support registers it\)\. /)
    lay_out(["proc/sys/fs/binfmt_misc/qemu-arm", "enabled\ninterpreter /usr/bin/qemu-arm-static\n"])
    expect { described_class.new("amd64", root: @dir).check("armhf") }.not_to raise_error
  end

  it "refuses to make a foreign chroot on this machine without emulation, before running mmdebstrap" do
    release = BuildRelease.new(@dir, "em")
    release.package("base/one")
    release.compile
    File.write(release.spec_path, File.read(release.spec_path).sub("bookworm: [amd64]", "bookworm: [amd64, s390x]"))
    expect(relspec("compile", "specs/em.yml", "--out", "out", "--no-check", chdir: @dir).exit_code).to eq(0)
    run = relspec("build", "specs/em.yml", "--out", "out", "--target", "bookworm/s390x", "--prepare", chdir: @dir)
    expect(run.exit_code).to eq(1)
    # bin/setup sets up no emulation, bin/emulation-smoke only arm64's: what
    # is missing for s390x depends on which of them ran on this machine
    missing = begin
      described_class.new("amd64").check("s390x")
    rescue Relspec::BuildError => e
      e.message
    end
    expect(missing).to start_with("cannot build s390x on this amd64 machine: ")
    expect(run.stderr).to eq("relspec: error: #{missing}\n")
    expect(File.exist?(File.join(release.dir, "out", "em", "bookworm-s390x", "logs", "prepare.log"))).to be(false)
  end
end
