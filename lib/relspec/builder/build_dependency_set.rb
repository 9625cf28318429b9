# frozen_string_literal: true

require "digest"
require "fileutils"
require_relative "../error"
require_relative "../frozen"
require_relative "../printable"

module Relspec
  module Builder
    # The exact packages and versions apt installs for a build's
    # build-dependencies, read from `apt-get --simulate satisfy`: the key of
    # a build-dependency layer (docs/build.md, "Build-dependency layers by
    # exact set"). Two builds may share a layer only when their sets are
    # equal, package for package and version for version: a layer holding
    # more than a build declares would hide a missing Build-Depends.
    #
    # apt's output comes from indices relspec does not control, so every
    # name, version and architecture is checked before it may name a layer
    # or become an argument of apt-get.
    class BuildDependencySet
      # One package apt would install.
      Package = Struct.new(:name, :version, :arch, keyword_init: true) do
        # apt-get install's argument for exactly this package.
        def to_s
          "#{name}:#{arch}=#{version}"
        end
      end

      # sbuild adds these to every build's Build-Depends (its $core_depends)
      CORE_DEPENDS = "build-essential, fakeroot"
      # `Inst name [installed version] (version releases [arch])`, apt's
      # line for a package it would unpack; the releases hold spaces
      INST = /\AInst (?<name>\S+) (?:\[[^\]]*\] )?\((?<version>\S+) .*\[(?<arch>[^\]]+)\]\)/
      NAME = /\A[a-z0-9][a-z0-9+.-]+\z/
      # Debian policy 5.6.12: epoch, upstream version, revision
      VERSION = /\A(?:[0-9]+:)?[0-9][A-Za-z0-9.+~:-]*\z/
      ARCH = /\A[a-z0-9][a-z0-9-]*\z/

      # apt-get's arguments that simulate installing +depends+ (lines in
      # Build-Depends syntax) with sbuild's own additions, as sbuild would.
      def self.simulate_arguments(depends)
        ["--simulate", "--no-install-recommends", "satisfy", *depends, CORE_DEPENDS]
      end

      # The command that simulates +depends+ in the chroot unpacked at
      # +root+ (its sources, lists and dpkg status) with this machine's
      # apt-get, writing nothing there: the lower layer is shared by every
      # build of the run. apt writes its cache and its solver's log
      # (eipp.log.xz, even when simulating) into +scratch+ instead, an empty
      # folder of the caller's. +options+: more of apt-get's (more sources).
      def self.simulate_command(root, scratch, depends, options = [])
        cache = File.join(scratch, "cache")
        FileUtils.mkdir_p(File.join(cache, "archives", "partial"))
        ["apt-get", "-o", "Dir=#{root}/", "-o", "Dir::Cache=#{cache}", "-o", "Dir::Log=#{scratch}",
         "-o", "Debug::NoLocking=1", *options, *simulate_arguments(depends)]
      end

      # The set in +output+, apt-get --simulate's (+source+ names where it
      # came from in an error).
      def self.from_simulation(output, source:)
        packages = output.each_line.filter_map do |line|
          match = INST.match(line.chomp) or next
          name = match[:name].delete_suffix(":#{match[:arch]}")
          check(name, NAME, "package name", source)
          check(match[:version], VERSION, "version", source)
          check(match[:arch], ARCH, "architecture", source)
          Package.new(name: name, version: match[:version], arch: match[:arch])
        end
        new(packages)
      end

      def self.check(value, pattern, what, source)
        return if value.match?(pattern)

        raise BuildError, "#{source}: apt would install a package with the #{what} \"#{Printable.text(value)}\""
      end
      private_class_method :check

      attr_reader :packages

      # +packages+: Package values, in any order (each package once).
      def initialize(packages)
        @packages = Frozen.deep(packages.uniq.sort_by { |package| [package.name, package.arch, package.version] })
        names = @packages.map { |package| [package.name, package.arch] }
        raise ArgumentError, "a package twice in a build-dependency set" if names.uniq.size != names.size

        freeze
      end

      def empty?
        packages.empty?
      end

      # apt-get install's arguments for exactly this set.
      def install_arguments
        packages.map(&:to_s)
      end

      # A name for the set's layer: the same for the same set, whatever
      # order apt printed it in, and different for any other.
      def key
        Digest::SHA256.hexdigest(install_arguments.map { |argument| "#{argument}\n" }.join)
      end

      def ==(other)
        other.is_a?(BuildDependencySet) && packages == other.packages
      end
      alias eql? ==

      def hash
        packages.hash
      end
    end
  end
end
