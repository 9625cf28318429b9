# frozen_string_literal: true

require_relative "../defaults"

module Relspec
  module ReleaseSpec
    # Where a release installs and how it names its Debian packages:
    # +install_prefix+ (/opt/rock), +separate_prefixes+ (each release below
    # its own <install_prefix>/<release>) and +package_prefix+ (rock).
    Prefixes = Struct.new(:install_prefix, :separate_prefixes, :package_prefix, keyword_init: true) do
      # +value+: key → value as written (nil when absent); absent keys take
      # their DEFAULTS.
      def self.from(value)
        new(install_prefix: value.call("install_prefix") || DEFAULTS["install_prefix"],
            separate_prefixes: value.call("separate_prefixes").then { |given| given.nil? ? DEFAULTS["separate_prefixes"] : given },
            package_prefix: value.call("package_prefix") || DEFAULTS["package_prefix"])
      end

      def initialize(**)
        super
        freeze
      end

      # The folder one of the release's packages installs into.
      def install_dir(release, deb_name)
        base = File.join(install_prefix, release)
        separate_prefixes ? File.join(base, deb_name) : base
      end
    end
  end
end
