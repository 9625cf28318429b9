# frozen_string_literal: true

require "fileutils"
require "securerandom"
require_relative "../error"
require_relative "build_user_folder"

module Relspec
  module Builder
    # The chroot of a target unpacked once per relspec run (the lower
    # layer) and a throw-away overlay layer over it for each sbuild build,
    # so that no build pays for unpacking the tarball and deleting the tree,
    # and no build sees another's changes: each writes only into its own
    # upper layer, removed when it ends.
    #
    # sbuild (0.85, and backports' 0.89) cannot do this itself: its unshare
    # mode always unpacks a tarball into a fresh folder (docs/build.md). So
    # relspec gives sbuild an empty tarball and runs it in a mount namespace
    # of its own (`unshare --mount`, which needs root) where the build's
    # overlay is mounted; `$unshare_bind_mounts` binds the overlay onto
    # sbuild's empty folder as the chroot's root first, before ccache's and
    # the apt cache's folders, in every command sbuild runs in the chroot.
    # The namespace, and the mount with it, ends with sbuild, also when it is
    # killed.
    #
    # The lower layer belongs to the chroot's users (the subordinate ids
    # sbuild maps them to): it is unpacked in a user namespace with sbuild's
    # mapping, and the sbuild user and group are added as sbuild would add
    # them (its --root useradd runs on the empty folder, not the overlay).
    class ChrootLayers
      # where sbuild sees the overlay bound
      ROOT = "/"
      # device nodes cannot be made in a user namespace (sbuild skips them too)
      DEVICES = %w[urandom random full null console zero tty ptmx].map { |name| "--exclude=./dev/#{name}" }.freeze
      # Shell for a chroot at "$1" entered as its root, as every sbuild
      # session has it: the host's device nodes bound (onto a file made
      # where the tarball has none, DEVICES) and /proc.
      SYSTEM_MOUNTS = "for f in null zero full random urandom; do { [ -e \"$1/dev/$f\" ] || touch \"$1/dev/$f\"; } && " \
                      "mount -o bind \"/dev/$f\" \"$1/dev/$f\" || exit 1; done && mount -t proc proc \"$1/proc\""

      # [first, count] of +user+'s range in +file+ (/etc/subuid, /etc/subgid).
      def self.range(file, user)
        first = BuildUserFolder.first_subordinate(file, user)
        count = File.foreach(file).find { |entry| entry.split(":").first == user }.split(":")[2].to_i
        [first, count]
      end

      # +tarball+: the target's chroot tarball (Chroot); +folder+: where the
      # layers go (this run's, removed at its end); +uids+, +gids+: [first,
      # count] of the subordinate ids sbuild maps the chroot's users to.
      def initialize(tarball, folder, uids:, gids:)
        @tarball = tarball
        @folder = folder
        @uids = uids
        @gids = gids
        @lock = Mutex.new
        @lower = nil
        check_path(folder)
      end

      # the run's folder of the target's layers
      attr_reader :folder, :uids, :gids

      # The empty tarball sbuild is given (it unpacks it into its folder).
      def empty_tarball
        path = File.join(@folder, "empty.tar")
        # two zero blocks: an archive of nothing
        File.binwrite(path, "\0" * 1024) unless File.file?(path)
        path
      end

      # Unpacks the lower layer unless done: +tool+ runs the unpacking for
      # +source+ into +log+. Returns its folder.
      def lower(tool, source, log)
        @lock.synchronize do
          @lower ||= unpack(tool, source, log)
        end
      end

      # Runs the block with a new layer over the lower one: [upper, work,
      # merged] folders; removes them when the block ends.
      def layer
        dir = File.join(@folder, "layer-#{SecureRandom.hex(6)}")
        upper, work, merged = %w[upper work merged].map { |name| File.join(dir, name) }
        FileUtils.mkdir_p([upper, work, merged], mode: 0o755)
        # the root of the chroot is the upper layer's folder
        File.chown(@uids.first, @gids.first, upper)
        yield upper, work, merged
      ensure
        FileUtils.rm_rf(dir) if dir
      end

      # The command that runs +command+ (sbuild's) with the overlay of
      # +upper+, +work+ and +merged+ over +lower+ mounted (folders joined by
      # ':', the uppermost first: a build-dependency layer over the lower one).
      def wrap(command, lower, upper, work, merged)
        ["unshare", "--mount", "--propagation", "private", "--", "sh", "-c",
         'mount -t overlay overlay -o "lowerdir=$1,upperdir=$2,workdir=$3" "$4" && shift 4 && exec "$@"',
         "sh", lower, upper, work, merged, *command]
      end

      # The lines of sbuild's configuration for a build on the layer whose
      # merged folder is +merged+: the overlay bound as the chroot's root,
      # before every other bind mount; and sbuild's steps that a throw-away
      # layer makes useless left out (docs/build.md): no apt-get update (the
      # lower layer's lists were refreshed once, #lower; the resolver still
      # updates the lists of its own archive, the --extra-package archive
      # and the --extra-repository lines), no removal of the build tree nor
      # of the session (the layer goes as a whole; the results are copied
      # out before), and sbuild's empty session folder in the layer's folder.
      def config_lines(merged)
        session = File.join(File.dirname(merged), "session.XXXXXXXXXX")
        ["unshift @{$unshare_bind_mounts}, { directory => #{BuildUserFolder.perl(merged)}, mountpoint => '#{ROOT}' };",
         "$apt_update = 0;", "$purge_build_directory = 'never';", "$purge_session = 'never';",
         "$unshare_tmpdir_template = #{BuildUserFolder.perl(session)};"]
      end

      # unshare's options for a user namespace with sbuild's mapping, root in it
      def namespace
        ["unshare", "--user", "--map-users=#{@uids[0]},0,#{@uids[1]}", "--map-groups=#{@gids[0]},0,#{@gids[1]}",
         "--setuid", "0", "--setgid", "0"]
      end

      private

      def unpack(tool, source, log)
        lower = File.join(@folder, "lower")
        FileUtils.rm_rf(lower)
        Dir.mkdir(lower, 0o755)
        File.chown(@uids.first, @gids.first, lower)
        # the tarball is read here (root's cache is closed to the chroot's users)
        tool.run(source, unpack_command(lower), log: log, stdin: @tarball, name: "unpacking the chroot")
        tool.run(source, refresh_command(lower), log: log, name: "refreshing the chroot's package lists")
        lower
      end

      # apt-get update in the lower layer, once per run, instead of in every
      # build: as the chroot's root (sbuild's mapping), with the device
      # nodes, /proc and the name servers every sbuild session gives it.
      def refresh_command(lower)
        [*namespace, "--mount", "--pid", "--fork", "--", "sh", "-c",
         "#{SYSTEM_MOUNTS} && cat /etc/resolv.conf > \"$1/etc/resolv.conf\" && " \
         "exec chroot \"$1\" apt-get -o Acquire::Languages=none update", "sh", lower]
      end

      def unpack_command(lower)
        add_user = "{ grep -q '^sbuild:' \"$1/etc/group\" || groupadd --root \"$1\" --system sbuild; } && " \
                   "{ grep -q '^sbuild:' \"$1/etc/passwd\" || useradd --root \"$1\" --system --home-dir " \
                   "/var/lib/sbuild --no-create-home --shell /bin/bash --gid sbuild --comment 'Debian source " \
                   "builder,,,' sbuild; }"
        [*namespace, "--", "sh", "-c",
         "zstd -dc | tar -C \"$1\" -x --numeric-owner #{DEVICES.join(' ')} && #{add_user}", "sh", lower]
      end

      # overlayfs's options are separated by commas and colons
      def check_path(path)
        return unless path.match?(/[,:\\]/)

        raise BuildError, "cannot lay a chroot out in #{path}: overlayfs takes no ',', ':' or '\\' in its folders"
      end
    end
  end
end
