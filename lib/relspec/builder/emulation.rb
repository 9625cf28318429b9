# frozen_string_literal: true

require_relative "../error"

module Relspec
  module Builder
    # Whether this machine can run a foreign architecture's binaries, which
    # a chroot of that architecture needs (mmdebstrap runs its maintainer
    # scripts, sbuild its compilers): qemu-user-static's emulator, its
    # binfmt_misc registration, and arch-test (mmdebstrap refuses a foreign
    # architecture without it). Says exactly what is missing and how to set
    # it up; relspec itself never installs or registers anything.
    class Emulation
      # Debian architecture => qemu's name, for those amd64 cannot run natively.
      QEMU = { "arm64" => "aarch64", "armhf" => "arm", "armel" => "arm", "ppc64el" => "ppc64le", "s390x" => "s390x",
               "riscv64" => "riscv64", "mips64el" => "mips64el", "i386" => nil, "amd64" => nil }.freeze
      # What an amd64 processor runs without emulation.
      NATIVE = { "amd64" => %w[amd64 i386], "arm64" => %w[arm64 armhf armel] }.freeze

      # +root+: where /usr/bin and /proc are (a test's fake root).
      def initialize(host_arch, root: "/")
        @host_arch = host_arch
        @root = root
      end

      def needed?(arch)
        !NATIVE.fetch(@host_arch, [@host_arch]).include?(arch)
      end

      # Raises BuildError naming every missing piece for +arch+.
      def check(arch)
        return unless needed?(arch)

        qemu = QEMU[arch] or
          raise BuildError, "cannot build #{arch} on this #{@host_arch} machine: relspec knows no emulator for it"
        missing = missing(qemu)
        return if missing.empty?

        raise BuildError, "cannot build #{arch} on this #{@host_arch} machine: #{missing.join('; ')}. " \
                          "To build by emulation: apt-get install qemu-user-static binfmt-support arch-test " \
                          "(this registers emulators machine-wide), or build on #{arch} nodes (docs/scale-out.md)"
      end

      private

      def missing(qemu)
        missing = []
        missing << "no emulator (/usr/bin/qemu-#{qemu}-static: qemu-user-static)" unless file?("usr/bin/qemu-#{qemu}-static")
        binfmt = "proc/sys/fs/binfmt_misc"
        if !file?("#{binfmt}/status")
          missing << "binfmt_misc is not mounted (/#{binfmt})"
        elsif !file?("#{binfmt}/qemu-#{qemu}") || !File.read(path("#{binfmt}/qemu-#{qemu}")).start_with?("enabled")
          missing << "no enabled binfmt_misc entry qemu-#{qemu} (binfmt-support registers it)"
        end
        missing << "no arch-test (/usr/bin/arch-test, which mmdebstrap needs for a foreign architecture)" unless file?("usr/bin/arch-test")
        missing
      end

      def file?(relative)
        File.file?(path(relative))
      end

      def path(relative)
        File.join(@root, relative)
      end
    end
  end
end
