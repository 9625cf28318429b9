# frozen_string_literal: true

require "etc"
require "fileutils"
require "find"
require_relative "../error"

module Relspec
  module Builder
    # A folder on this machine that sbuild binds into its unshare chroots
    # and that the chroot's users write (the compiler cache, Ccache; the
    # downloaded build-dependencies, AptCache).
    #
    # sbuild's unshare mode maps the chroot's users to this user's
    # subordinate ids (/etc/subuid), and runs a build of root's as the
    # chroot's root, i.e. as the first subordinate uid. The folder is owned
    # by that uid and gid and closed to everybody else (0700): never
    # world-writable, because whoever writes it chooses what later builds
    # use. Only root can give a folder to a subordinate uid, so such a folder
    # exists when relspec runs as root; a normal user's builds go without.
    class BuildUserFolder
      # The folder +env+[+variable+] chooses ("off": none, else an absolute
      # folder), else +default+ when relspec runs as root; nil when there is
      # none. +what+ names it in messages. +uid+ and +user+: who runs
      # relspec; +subuid+, +subgid+: the files sbuild reads the id mapping
      # from.
      def self.from_environment(env, variable:, default:, what:, uid: Process.uid, user: Etc.getpwuid(uid)&.name,
                                subuid: "/etc/subuid", subgid: "/etc/subgid")
        setting = env.fetch(variable, "")
        return nil if setting == "off" || (setting.empty? && !uid.zero?)

        dir = setting.empty? ? default : setting
        raise BuildError, "#{variable}=#{setting}: not an absolute folder (or \"off\")" unless dir.start_with?("/")
        unless uid.zero?
          raise BuildError, "#{variable}=#{setting}: #{what} in sbuild's chroot needs relspec to run as root " \
                            "(its folder must belong to a subordinate uid); set #{variable}=off"
        end

        # read when the folder is made: a Slurm submit host builds nothing here
        # and may have no subordinate ids
        new(File.expand_path(dir), what: what, variable: variable,
                                   owner: -> { [first_subordinate(subuid, user), first_subordinate(subgid, user)] })
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

      # A Perl single-quoted string (sbuild's configuration is Perl).
      def self.perl(text)
        "'#{text.gsub(/[\\']/) { |char| "\\#{char}" }}'"
      end

      attr_reader :dir

      # +dir+: the folder on this machine; +owner+: [uid, gid] the chroot's
      # build user has on this machine (or a lambda returning them);
      # +what+ and +variable+: its name and setting in messages.
      def initialize(dir, owner:, what:, variable:)
        @dir = dir
        @owner = owner
        @what = what
        @variable = variable
        @lock = Mutex.new
        @ready = false
      end

      # [uid, gid] of the chroot's build user on this machine.
      def owner
        @owner = @owner.call if @owner.respond_to?(:call)
        @owner
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
      # run's or the user's own: one of another user (a variable naming it by
      # mistake, or to have root hand it over) stays theirs and is refused
      # by check_owner, as a foreign folder that holds files is.
      def handed_over?(created)
        stat = File.stat(@dir)
        stat.uid != owner.first && Dir.empty?(@dir) && (created || stat.uid == Process.uid)
      end

      def check_folder
        return if File.directory?(@dir) && !File.symlink?(@dir)

        raise BuildError, "#{@what} folder #{@dir} is not a folder (#{@variable} chooses another, \"off\" none)"
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

        raise BuildError, "#{@what} folder #{@dir} belongs to uid #{uid}, not to the uid sbuild's build user has " \
                          "here (#{owner.first}): chown -R #{owner.join(':')} it, or remove it"
      end
    end
  end
end
