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

      def self.known?(name)
        KNOWN.include?(name)
      end
    end
  end
end
