# frozen_string_literal: true

require_relative "build_user_folder"

module Relspec
  module Builder
    # The compiler cache (ccache) of sbuild's C and C++ builds: one folder on
    # this machine, bound into every build's unshare chroot, so that a
    # rebuild after a blacklist or pin change (a new version, built in
    # another folder) takes the objects of unchanged sources from it.
    #
    # sbuild 0.85 reads it all from the file named by SBUILD_CONFIG
    # (#config_lines): `$unshare_bind_mounts` binds the folder,
    # `$build_environment` points ccache at it, `$path` puts ccache's
    # compiler links (/usr/lib/ccache) first, and `$manual_depends` adds
    # ccache to the build-dependencies. The chroot tarball includes ccache
    # (Chroot::INCLUDE), so that dependency costs nothing there; a tarball
    # made before has apt install it in each build instead, which is why
    # relspec need not tell the two tarballs apart.
    #
    # Who writes it: the chroot's build user only (BuildUserFolder, 0700):
    # whoever writes a compile cache chooses the objects of every later
    # build. So ccache is used when relspec runs as root; a normal user's
    # builds go without it.
    class Ccache
      # where relspec run by root keeps it (root's home is closed to the
      # chroot's users)
      DEFAULT_DIR = "/var/cache/relspec/ccache"
      # where the build sees it
      MOUNTPOINT = "/var/cache/ccache"
      # what sbuild installs in every build for it ($manual_depends)
      PACKAGE = "ccache"
      # ccache's own limit: it removes the oldest objects beyond it
      MAX_SIZE = "5G"
      # sbuild's default PATH of a build, ccache's compiler links first
      PATH = "/usr/lib/ccache:/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin:/usr/games"
      # The environment variable choosing the folder ("off": no ccache).
      VARIABLE = "RELSPEC_CCACHE"

      # The ccache of this run, nil when there is none: +env+'s
      # RELSPEC_CCACHE ("off", or an absolute folder), else DEFAULT_DIR when
      # relspec runs as root (BuildUserFolder.from_environment: +uid+,
      # +user+, +subuid+, +subgid+).
      def self.from_environment(env = ENV, **who)
        folder = BuildUserFolder.from_environment(env, variable: VARIABLE, default: DEFAULT_DIR, what: "ccache", **who)
        folder && new(folder)
      end

      # +folder+: a BuildUserFolder, or the folder's path with +owner+:
      # [uid, gid] the chroot's build user has on this machine.
      def initialize(folder, owner: nil)
        folder = BuildUserFolder.new(folder, owner: owner, what: "ccache", variable: VARIABLE) unless folder.is_a?(BuildUserFolder)
        @folder = folder
      end

      def dir
        @folder.dir
      end

      # [uid, gid] of the chroot's build user on this machine.
      def owner
        @folder.owner
      end

      # Makes the folder, or checks its owner and closes it (BuildUserFolder).
      def prepare
        @folder.prepare
      end

      # The lines of sbuild's configuration that use the cache (#prepare
      # first). Pushed onto the bind mounts: AptCache binds its folder too.
      def config_lines
        prepare
        ["push @{$unshare_bind_mounts}, { directory => #{BuildUserFolder.perl(dir)}, mountpoint => #{BuildUserFolder.perl(MOUNTPOINT)} };",
         # BASEDIR: the compiler's paths below /build (a build's folder,
         # /build/<source>-<random>/<source>-<version>) hashed relative, so
         # that another build folder finds the same objects
         "$build_environment = { 'CCACHE_DIR' => #{BuildUserFolder.perl(MOUNTPOINT)}, 'CCACHE_BASEDIR' => '/build', " \
         "'CCACHE_MAXSIZE' => #{BuildUserFolder.perl(MAX_SIZE)} };",
         "$path = #{BuildUserFolder.perl(PATH)};",
         "$manual_depends = [#{BuildUserFolder.perl(PACKAGE)}];"]
      end
    end
  end
end
