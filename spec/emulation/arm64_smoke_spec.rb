# frozen_string_literal: true

require "spec_helper"
require "open3"
require_relative "../support/build_release"

# A foreign architecture by emulation, for real: on an amd64 machine,
# mmdebstrap makes a bookworm/arm64 chroot (its maintainer scripts run in
# qemu-user-static through binfmt_misc) and sbuild builds a small C
# program in it with arm64's own compiler. The .deb says arm64, its program
# is an AArch64 binary, and it runs under qemu.
#
# It takes about 7 minutes (most of it the chroot), so bin/test does not run
# it: bin/emulation-smoke sets up the emulation and runs this file
# (docs/scale-out.md).
RSpec.describe "an arm64 build by emulation", order: :defined do
  em_aarch64 = 183 # ELF e_machine of AArch64
  emulator = "/usr/bin/qemu-aarch64-static"

  before(:all) do
    @dir = Dir.mktmpdir("relspec-emulation")
    @release = BuildRelease.new(@dir, "emu")
    # statically linked, so that qemu runs it without an arm64 libc around it
    @release.package("base/hello", cmake: <<~CMAKE)
      enable_language(C)
      file(WRITE ${CMAKE_BINARY_DIR}/hello.c "#include <stdio.h>\\nint main(void) { printf(\\"hello from a %zu-bit %s\\\\n\\", sizeof(void *) * 8, \\"build\\"); return 0; }\\n")
      add_executable(rock-hello ${CMAKE_BINARY_DIR}/hello.c)
      target_link_options(rock-hello PRIVATE -static)
      install(TARGETS rock-hello DESTINATION bin)
    CMAKE
    @release.compile(targets: "{ bookworm: [arm64] }")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  it "builds a package in an emulated arm64 chroot whose program runs under qemu" do
    run = relspec("build", "specs/emu.yml", "--out", "out", "--backend", "sbuild", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(run.stdout).to include("bookworm/arm64: 1 built")

    name = "#{@release.source('base/hello')}_1.0.20200301.000000-1~bookworm_arm64.deb"
    deb = Dir.glob(File.join(@release.target_dir("bookworm-arm64"), "**", name)).first
    expect(deb).not_to be_nil, "no #{name} in #{@release.target_dir('bookworm-arm64')}"
    architecture, = Open3.capture2("dpkg-deb", "--field", deb, "Architecture")
    expect(architecture).to eq("arm64\n")

    unpacked = File.join(@dir, "unpacked")
    system("dpkg-deb", "--extract", deb, unpacked, exception: true)
    program = Dir.glob(File.join(unpacked, "**", "bin", "rock-hello")).first
    expect(program).not_to be_nil
    header = File.binread(program, 20)
    expect(header[0, 4]).to eq("\x7FELF".b)
    expect(header[18, 2].unpack1("v")).to eq(em_aarch64)

    output, status = Open3.capture2e(emulator, program)
    expect(status.success?).to be(true), output
    expect(output).to eq("hello from a 64-bit build\n")
  end
end
