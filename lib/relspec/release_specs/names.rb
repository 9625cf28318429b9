# frozen_string_literal: true

require_relative "../debian_name"

module Relspec
  module ReleaseSpec
    # The shapes that names must have before relspec lets them become Debian
    # package names, file names or paths.
    module Names
      RELEASE = /\A[a-z][a-z0-9.+-]*\z/
      # autoproj package names: path-like segments of letters, digits, _ . + -
      PACKAGE = %r{\A[A-Za-z0-9_.+-]+(/[A-Za-z0-9_.+-]+)*\z}
      # the leading part of Debian package names
      DEBIAN_PREFIX = DebianName::PREFIX
      GEM = /\A[A-Za-z0-9][A-Za-z0-9._-]*\z/
      GEM_VERSION = /\A[0-9]+(\.[0-9A-Za-z]+)*\z/
      CODENAME = /\A[a-z][a-z0-9-]*\z/
      COMMIT = /\A[0-9a-f]{7,40}\z/
      # "Name <address>", as debian/control wants it (one line)
      MAINTAINER = /\A[^<>[:cntrl:]]+ <[^<>\s]+@[^<>\s]+>\z/
      # where packages install: it ends up in debian/rules and in env.sh
      INSTALL_PREFIX = %r{\A(/[A-Za-z0-9._+-]+)+\z}

      RELEASE_HINT = "release names use lowercase letters, digits and . + - , starting with a letter (e.g. master-20.06)"

      module_function

      def release?(name)
        name.is_a?(String) && RELEASE.match?(name)
      end

      def package?(name)
        name.is_a?(String) && PACKAGE.match?(name)
      end
    end
  end
end
