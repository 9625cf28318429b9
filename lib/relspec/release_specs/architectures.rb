# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # Debian architecture names a target may list; anything else is almost
    # always a typo (x86_64, aarch64) that would silently build nothing.
    module Architectures
      KNOWN = %w[amd64 arm64 armel armhf i386 mips64el mipsel ppc64el riscv64 s390x].freeze

      # Names other tools use for the same machines, to turn a typo into a hint.
      ALIASES = { "x86_64" => "amd64", "aarch64" => "arm64", "x86" => "i386", "i686" => "i386",
                  "arm" => "armhf", "ppc64le" => "ppc64el" }.freeze

      # Debian's multiarch tuple of each: where the distribution's Ruby keeps
      # its extensions (/usr/lib/<tuple>/ruby/<abi>), the folder a CMake
      # package asking Ruby for its archdir installs its bindings into.
      MULTIARCH = { "amd64" => "x86_64-linux-gnu", "arm64" => "aarch64-linux-gnu", "armel" => "arm-linux-gnueabi",
                    "armhf" => "arm-linux-gnueabihf", "i386" => "i386-linux-gnu", "mips64el" => "mips64el-linux-gnuabi64",
                    "mipsel" => "mipsel-linux-gnu", "ppc64el" => "powerpc64le-linux-gnu",
                    "riscv64" => "riscv64-linux-gnu", "s390x" => "s390x-linux-gnu" }.freeze

      def self.known?(name)
        KNOWN.include?(name)
      end
    end
  end
end
