# frozen_string_literal: true

require "etc"
require "fileutils"
require "find"
require_relative "../error"

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
    # Who writes it: sbuild's unshare mode maps the chroot's users to this
    # user's subordinate ids (/etc/subuid), and runs a build of root's as
    # the chroot's root, i.e. as the first subordinate uid. The folder is
    # owned by that uid and gid and closed to everybody else (0700): never
    # world-writable, because whoever writes a compile cache chooses the
    # objects of every later build. Only root can give a folder to a
    # subordinate uid, so ccache is used when relspec runs as root; a
    # normal user's builds go without it.
    class Ccache
      # where relspec run by root keeps it (root's home is closed to the
      # chroot's users)
      DEFAULT_DIR = "/var/cache/relspec/ccache"
      # where the build sees it
      MOUNTPOINT = "/var/cache/ccache"
      # ccache's own limit: it removes the oldest objects beyond it
      MAX_SIZE = "5G"
      # sbuild's default PATH of a build, ccache's compiler links first
      PATH = "/usr/lib/ccache:/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin:/usr/games"
      # The environment variable choosing the folder ("off": no ccache).
      VARIABLE = "RELSPEC_CCACHE"

      # The ccache of this run, nil when there is none: +env+'s
      # RELSPEC_CCACHE ("off", or an absolute folder), else DEFAULT_DIR when
      # relspec runs as root. +uid+ and +user+: who runs relspec; +subuid+,
      # +subgid+: the files sbuild reads the id mapping from.
      def self.from_environment(env = ENV, uid: Process.uid, user: Etc.getpwuid(uid)&.name,
                                subuid: "/etc/subuid", subgid: "/etc/subgid")
        setting = env.fetch(VARIABLE, "")
        return nil if setting == "off" || (setting.empty? && !uid.zero?)

        dir = setting.empty? ? DEFAULT_DIR : setting
        raise BuildError, "#{VARIABLE}=#{setting}: not an absolute folder (or \"off\")" unless dir.start_with?("/")
        unless uid.zero?
          raise BuildError, "#{VARIABLE}=#{setting}: ccache in sbuild's chroot needs relspec to run as root " \
                            "(its folder must belong to a subordinate uid); set #{VARIABLE}=off"
        end

        # read when the folder is made: a Slurm submit host builds nothing here
        # and may have no subordinate ids
        new(File.expand_path(dir), owner: -> { [first_subordinate(subuid, user), first_subordinate(subgid, user)] })
      end

      # The first id of +user+'s range in +file+ (/etc/subuid or
      # /etc/subgid), as sbuild takes it.
      def self.first_subordinate(file, user)
        line = File.exist?(file) ? File.foreach(file).find { |entry| entry.split(":").first == user } : nil
        raise BuildError, "no subordinate ids of #{user} in #{file}, which sbuild's unshare mode needs" unless line

        Integer(line.split(":")[1], 10)
      rescue ArgumentError
        raise BuildError, "#{file}: the entry of #{user} is not a number"
      end

      attr_reader :dir

      # +dir+: the folder on this machine; +owner+: [uid, gid] the chroot's
      # build user has on this machine (or a lambda returning them).
      def initialize(dir, owner:)
        @dir = dir
        @owner = owner
        @lock = Mutex.new
        @ready = false
      end

      # [uid, gid] of the chroot's build user on this machine.
      def owner
        @owner = @owner.call if @owner.respond_to?(:call)
        @owner
      end

      # The lines of sbuild's configuration that use the cache (#prepare
      # first).
      def config_lines
        prepare
        ["$unshare_bind_mounts = [ { directory => #{perl(@dir)}, mountpoint => #{perl(MOUNTPOINT)} } ];",
         # BASEDIR: the compiler's paths below /build (a build's folder,
         # /build/<source>-<random>/<source>-<version>) hashed relative, so
         # that another build folder finds the same objects
         "$build_environment = { 'CCACHE_DIR' => #{perl(MOUNTPOINT)}, 'CCACHE_BASEDIR' => '/build', " \
         "'CCACHE_MAXSIZE' => #{perl(MAX_SIZE)} };",
         "$path = #{perl(PATH)};",
         "$manual_depends = ['ccache'];"]
      end

      # Makes the folder, or checks its owner and closes it, once: raises
      # BuildError when it is no folder or belongs to someone else.
      def prepare
        @lock.synchronize do
          next if @ready

          FileUtils.mkdir_p(File.dirname(@dir), mode: 0o755)
          created = !File.exist?(@dir) && !File.symlink?(@dir)
          Dir.mkdir(@dir, 0o700) if created
          check_folder
          File.chown(*owner, @dir) if handed_over?(created)
          check_owner
          hand_back_contents
          # nobody but the build user writes (or reads) it
          File.chmod(0o700, @dir)
          @ready = true
        end
      end

      private

      # An empty folder is given to the build user only when it is this
      # run's or the user's own: one of another user (RELSPEC_CCACHE naming
      # it by mistake, or to have root hand it over) stays theirs and is
      # refused by check_owner, as a foreign folder that holds files is.
      def handed_over?(created)
        stat = File.stat(@dir)
        stat.uid != owner.first && Dir.empty?(@dir) && (created || stat.uid == Process.uid)
      end

      def check_folder
        return if File.directory?(@dir) && !File.symlink?(@dir)

        raise BuildError, "ccache folder #{@dir} is not a folder (#{VARIABLE} chooses another, \"off\" none)"
      end

      # Gives the build user what someone else (root) made inside the folder:
      # `ccache -C` or `ccache -z` run as root on it writes root's stats files
      # and folders, after which every compile in a chroot stops at
      # "Permission denied" (a core release run lost five packages and all
      # behind them to it). The folder is the build user's, so its contents
      # are too; lchown never follows a link out of it.
      def hand_back_contents
        return unless Process.uid.zero?

        uid, gid = owner
        Find.find(@dir) do |path|
          stat = File.lstat(path)
          File.lchown(uid, gid, path) unless stat.uid == uid && stat.gid == gid
        end
      end

      def check_owner
        uid = File.stat(@dir).uid
        return if uid == owner.first

        raise BuildError, "ccache folder #{@dir} belongs to uid #{uid}, not to the uid sbuild's build user has " \
                          "here (#{owner.first}): chown -R #{owner.join(':')} it, or remove it"
      end

      # A Perl single-quoted string.
      def perl(text)
        "'#{text.gsub(/[\\']/) { |char| "\\#{char}" }}'"
      end
    end
  end
end
