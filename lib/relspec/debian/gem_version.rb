# frozen_string_literal: true

require "rubygems"
require_relative "../apt/version"

module Relspec
  module Debian
    # The one mapping between gem versions and Debian versions, both ways:
    # a gem packaged here gets its version as the Debian upstream version
    # (a prerelease sorts before its release only with a tilde), and a
    # distribution's ruby-<gem> package is read back as the gem version it
    # packages (without the distribution's repack suffix).
    module GemVersion
      # Suffixes distributions add to a repacked upstream (1.2.0+dfsg).
      REPACK = /[+~](dfsg|ds|repack).*\z/

      module_function

      # A gem version as a Debian upstream version: "1.0.0.pre" → "1.0.0~pre".
      def to_debian(version)
        version.to_s.sub(/\.(?=[A-Za-z])/, "~")
      end

      # The upstream part of a Debian version, without a repack suffix
      # (1.2.0+dfsg-1 → 1.2.0), and of a version gone back the Debian way
      # the one really packaged (3.1.1+really3.0.1-1 → 3.0.1).
      def debian_upstream(deb_version)
        Apt::Version.parse(deb_version).upstream.sub(/\A.*\+really/, "").sub(REPACK, "")
      end

      # The gem version a distribution's ruby-* package version packages
      # (1.2.0+dfsg-1 → 1.2.0, 1.0.0~pre-1 → 1.0.0.pre, 3.1.1+really3.0.1-1
      # → 3.0.1), or nil.
      def from_debian(deb_version)
        text = debian_upstream(deb_version).tr("~", ".")
        Gem::Version.correct?(text) ? Gem::Version.new(text) : nil
      end
    end
  end
end
