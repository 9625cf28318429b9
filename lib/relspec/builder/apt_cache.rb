# frozen_string_literal: true

require "fileutils"
require_relative "build_user_folder"

module Relspec
  module Builder
    # The .debs apt downloaded for sbuild's builds, kept per target
    # (<folder>/<codename>-<arch>) and shared by every build of it: the
    # second build that needs cmake takes cmake's .deb from here instead of
    # downloading it again.
    #
    # Each build keeps its own /var/cache/apt/archives (apt's lock and
    # partial downloads stay in its chroot, so two builds at once never
    # wait for or write over each other). The target's folder is bound
    # read-write at MOUNTPOINT; before the build-dependencies are installed
    # (sbuild's chroot-setup-commands) every kept .deb is linked into
    # the build's archives, and once they are installed
    # (starting-build-commands) each .deb apt downloaded is copied to a
    # temporary name and renamed into the folder, so a build never sees a
    # half-written file. apt uses a file in its archives only when its hash
    # is the one the (signed) index gives, and downloads it otherwise: the
    # folder holds no trust. Having more .debs at hand installs nothing: a
    # missing Build-Depends still fails.
    #
    # The folder belongs to the chroot's root (BuildUserFolder), so it is
    # there when relspec runs as root; RELSPEC_APT_CACHE chooses another
    # folder or "off".
    class AptCache
      DEFAULT_DIR = "/var/cache/relspec/apt"
      VARIABLE = "RELSPEC_APT_CACHE"
      # where a build sees its target's folder
      MOUNTPOINT = "/var/cache/relspec-apt"
      # apt's download folder in the chroot
      ARCHIVES = "/var/cache/apt/archives"

      # The cache of this run, nil when there is none (see
      # BuildUserFolder.from_environment for +who+).
      def self.from_environment(env = ENV, **who)
        folder = BuildUserFolder.from_environment(env, variable: VARIABLE, default: DEFAULT_DIR,
                                                       what: "apt download cache", **who)
        folder && new(folder)
      end

      # Shell: links every kept .deb of +kept+ into +archives+.
      def self.link_script(kept = MOUNTPOINT, archives = ARCHIVES)
        "find #{kept} -maxdepth 1 -type f -name '*.deb' -exec ln -sf -t #{archives} {} +"
      end

      # Shell: copies each .deb apt downloaded into +archives+ (files, not
      # the links of .link_script, nor sbuild's package of the build's
      # dependencies) into +kept+, under a temporary name of its own first
      # (mktemp: builds at once have the same pids in their namespaces). A
      # failed copy is said and costs the build nothing.
      def self.keep_script(kept = MOUNTPOINT, archives = ARCHIVES)
        "for deb in #{archives}/*.deb; do [ -f \"$deb\" ] && [ ! -L \"$deb\" ] || continue; " \
          "name=${deb##*/}; case $name in sbuild-build-depends-*) continue;; esac; partial=$(mktemp \"#{kept}/.$name.XXXXXX\") && cp \"$deb\" \"$partial\" && " \
          "mv -f \"$partial\" \"#{kept}/$name\" || " \
          "{ rm -f \"$partial\"; echo \"relspec: could not keep $name in the apt download cache\"; }; done; true"
      end

      # +folder+: the BuildUserFolder holding a folder per target.
      def initialize(folder)
        @folder = folder
        @lock = Mutex.new
      end

      def dir
        @folder.dir
      end

      # Makes the folder (BuildUserFolder#prepare).
      def prepare
        @folder.prepare
      end

      # The target's folder on this machine.
      def target_dir(target)
        File.join(dir, target.dir_name)
      end

      # The lines of sbuild's configuration that bind +target+'s folder and
      # link and keep its .debs (#prepare first).
      def config_lines(target)
        kept = target_folder(target)
        ["push @{$unshare_bind_mounts}, { directory => #{BuildUserFolder.perl(kept)}, mountpoint => #{BuildUserFolder.perl(MOUNTPOINT)} };",
         # sbuild has apt delete what it installed by default
         "$apt_keep_downloaded_packages = 1;",
         # a string: sbuild runs an external command as `sh -c` of its words
         # joined, so it is one script either way
         "push @{$external_commands->{'chroot-setup-commands'}}, #{BuildUserFolder.perl(AptCache.link_script)};",
         "push @{$external_commands->{'starting-build-commands'}}, #{BuildUserFolder.perl(AptCache.keep_script)};"]
      end

      # The target's folder, made for the build user once.
      def target_folder(target)
        prepare
        path = target_dir(target)
        @lock.synchronize do
          unless File.directory?(path) && !File.symlink?(path)
            raise BuildError, "apt download cache folder #{path} is not a folder" if File.symlink?(path) || File.exist?(path)

            Dir.mkdir(path, 0o700)
            File.chown(*@folder.owner, path) if Process.uid.zero?
          end
        end
        path
      end
    end
  end
end
