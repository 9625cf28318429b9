# frozen_string_literal: true

require "fileutils"
require "open3"
require_relative "../error"
require_relative "../release_specs/values/archive"
require_relative "../cache_dir"
require_relative "../temporaries"
require_relative "emulation"
require_relative "shell_line"

module Relspec
  module Builder
    # The chroot tarball sbuild builds in, one per codename/arch, made once
    # with `mmdebstrap --variant=buildd --mode=unshare` (plus debhelper) and kept in
    # relspec's cache (<cache>/chroots/<codename>-<arch>.tar.zst) for every
    # later build and release.
    #
    # The tarball keeps apt's lists: sbuild's `apt-get update` in each build
    # then only asks whether the archive moved (and fetches what changed
    # when it did) instead of downloading every index again. dpkg in the
    # chroot runs with force-unsafe-io: the chroot is thrown away after
    # each build, so fsync while installing build-dependencies buys nothing.
    #
    # The mirror is the spec's `distributions.<codename>.archive` (url, plus
    # its components), else this machine's own apt sources when the codename
    # is the host's (archive `host: true`, or no archive at all).
    class Chroot
      # Every package relspec emits build-depends on debhelper: in the
      # tarball once, rather than installed again by every build. ccache:
      # every build with the compiler cache (Ccache) depends on it; in the
      # tarball, that costs a build nothing (a tarball made without it has
      # apt install it in each build, which works the same, only slower).
      # fakeroot: sbuild adds it to every build's dependencies itself, so
      # having it hides no missing Build-Depends.
      INCLUDE = %w[debhelper ccache fakeroot].freeze
      # the lists kept (see above), dpkg without fsync in every later build
      SPEED = %w[--skip=cleanup/apt/lists --dpkgopt=force-unsafe-io].freeze
      # ccache's compiler links (/usr/lib/ccache) made again once everything
      # is installed: its postinst ran before the compilers' alternatives
      # existed, and without its `c++` and `cc` CMake finds /usr/bin/c++
      HOOKS = %w[--chrooted-customize-hook=update-ccache-symlinks].freeze
      # The first line of every apt source relspec's package set writes
      # (Osdeps::PackageSet's init.rb).
      PACKAGE_SET_SOURCE = "# written by relspec's autoproj package set"

      # This machine's apt sources of its distribution, read when a chroot
      # is made: every non-empty source file but those relspec's package
      # set wrote for a workspace (a release repository is not the
      # distribution, and a chroot made with one would need its server).
      def self.host_sources(etc = "/etc/apt")
        ["#{etc}/sources.list", *Dir.glob("#{etc}/sources.list.d/*.{list,sources}").sort].select do |file|
          next false unless File.file?(file)

          text = File.read(file)
          !text.strip.empty? && !text.start_with?(PACKAGE_SET_SOURCE)
        end
      end

      attr_reader :path

      # +distribution+: ReleaseSpec::Distribution of the codename; +os_release+:
      # the host's /etc/os-release (read to know the host's own codename).
      # +emulation+: checks that this machine runs the target's binaries.
      def initialize(target, distribution, tool, cache_dir: CacheDir.for("chroots"), os_release: "/etc/os-release",
                     emulation: Emulation.new(Chroot.host_arch))
        @target = target
        @distribution = distribution
        @tool = tool
        raise BuildError, "no cache folder for chroot tarballs (set XDG_CACHE_HOME or HOME)" unless cache_dir

        @path = File.join(cache_dir, "#{target.dir_name}.tar.zst")
        @os_release = os_release
        @emulation = emulation
      end

      # This machine's Debian architecture.
      def self.host_arch
        output, status = Open3.capture2("dpkg", "--print-architecture")
        status.success? ? output.strip : "amd64"
      end

      def exist?
        File.file?(@path)
      end

      # Makes the tarball unless it exists; +log+ receives mmdebstrap's output.
      # Returns true when one was made.
      def ensure(log)
        return false if exist?

        @emulation.check(@target.arch)
        mirrors = mirrors_or_raise
        FileUtils.mkdir_p(File.dirname(@path))
        # a killed mmdebstrap leaves hundreds of MB behind
        Temporaries.sweep(File.dirname(@path))
        partial = Temporaries.path(File.dirname(@path), File.basename(@path, ".tar.zst"), suffix: ".tar.zst")
        begin
          @tool.run("chroot #{@target}", command(partial, mirrors), log: log)
          File.rename(partial, @path)
        ensure
          FileUtils.rm_f(partial)
        end
        true
      end

      # Shell lines that make the tarball where it is missing (a Slurm
      # chroot-prepare job, on a node of the target's architecture).
      def job_steps
        # mmdebstrap picks the format by the name's ending
        partial = File.join(File.dirname(@path), ".#{File.basename(@path, '.tar.zst')}.partial.tar.zst")
        ["if [ ! -f #{ShellLine.quote(@path)} ]; then mkdir -p #{ShellLine.quote(File.dirname(@path))} && " \
         "#{ShellLine.join(command(partial, mirrors_or_raise))} && mv #{ShellLine.quote(partial)} " \
         "#{ShellLine.quote(@path)}; fi"]
      end

      private

      def command(partial, mirrors)
        ["mmdebstrap", "--variant=buildd", "--mode=unshare", "--arch=#{@target.arch}", "--include=#{INCLUDE.join(',')}",
         *SPEED, *HOOKS, *components_option, @target.codename, partial, *mirrors]
      end

      def archive
        @distribution&.archive || ReleaseSpec::Archive.new
      end

      def components_option
        components = archive.components
        components && !archive.host? ? ["--components=#{components.join(',')}"] : []
      end

      def mirrors_or_raise
        return [archive.url] if archive.url && !archive.host?

        if host_codename == @target.codename
          sources = Chroot.host_sources
          return sources unless sources.empty?
        end
        raise BuildError, "cannot make the chroot for #{@target}: no mirror of #{@target.codename} " \
                          "(set distributions.#{@target.codename}.archive.url in the spec; this machine's apt sources " \
                          "are used only when the codename is the host's own, here #{host_codename || 'unknown'})"
      end

      def host_codename
        File.file?(@os_release) ? File.read(@os_release)[/^VERSION_CODENAME=(\S+)/, 1] : nil
      end
    end
  end
end
