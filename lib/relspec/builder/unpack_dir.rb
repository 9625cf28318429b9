# frozen_string_literal: true

require "digest"
require "fileutils"
require "open3"
require "tmpdir"
require_relative "../temporaries"

module Relspec
  module Builder
    # Where sbuild (unshare mode) unpacks the chroot of one build: in memory
    # (tmpfs, /dev/shm) when this machine has room for it, else sbuild's own
    # default on disk (/tmp). Unpacking the tarball and deleting the tree
    # after the build cost seconds each on a loaded disk and a fraction of
    # a second on tmpfs (docs/performance.md).
    #
    # sbuild 0.85 reads `$unshare_tmpdir_template` from the file named by
    # SBUILD_CONFIG, so this machine's sbuild configuration is not touched.
    # The chroots go into one folder per relspec process, named as
    # Temporaries names it, removed when the run ends (#close); a build
    # killed with its relspec leaves its tree there, and the next relspec run
    # that builds with sbuild removes it.
    class UnpackDir
      SHM = "/dev/shm"
      # Room a build needs on tmpfs and in free memory: a Rock package's
      # chroot with its build-dependencies and build tree is a few GB, and
      # other builds run beside it.
      NEEDED = 6 * (1024**3)

      # Bytes free in the file system of +dir+ (df; Ruby has no statvfs),
      # nil when unknown.
      def self.free_bytes(dir)
        df(dir, "avail")
      end

      # Bytes of the file system of +dir+, nil when unknown.
      def self.size_bytes(dir)
        df(dir, "size")
      end

      # df's +field+ of the file system of +dir+ in bytes, nil when unknown.
      def self.df(dir, field)
        output, status = Open3.capture2("df", "--output=#{field}", "-B1", dir, err: File::NULL)
        status.success? ? output.lines.last.to_i : nil
      rescue SystemCallError
        nil
      end

      # Bytes of memory available (+meminfo+: /proc/meminfo), nil when unknown.
      def self.available_memory(meminfo)
        kib = File.read(meminfo)[/^MemAvailable:\s+(\d+) kB/, 1]
        kib && (kib.to_i * 1024)
      rescue SystemCallError
        nil
      end

      # +shm+: the tmpfs folder; +meminfo+: /proc/meminfo; +needed+: bytes
      # of tmpfs and of available memory a build needs to unpack there;
      # +free_bytes+: how the tmpfs's free bytes are asked.
      def initialize(shm: SHM, meminfo: "/proc/meminfo", needed: NEEDED, free_bytes: UnpackDir.method(:free_bytes))
        @shm = shm
        @meminfo = meminfo
        @needed = needed
        @free_bytes = free_bytes
        @lock = Mutex.new
        @root = nil
        @disk = nil
      end

      # The environment of one sbuild run: SBUILD_CONFIG naming a file that
      # puts the chroot on tmpfs, or nothing (sbuild's default) when tmpfs
      # or memory is short now. +extra+: more lines of that file (Ccache's, AptCache's),
      # written also when the chroot goes to disk.
      def environment(extra = [])
        on_tmpfs = room?
        return {} if !on_tmpfs && extra.empty?

        { "SBUILD_CONFIG" => config(on_tmpfs, extra) }
      end

      # A folder +name+ in this process's folder, on tmpfs when there is
      # room now, else on disk (ChrootLayers lays a target's chroot out in
      # it); removed by #close like the rest.
      def folder(name)
        on_tmpfs = room?
        @lock.synchronize do
          root = on_tmpfs ? (@root ||= make_root) : (@disk ||= make_disk_root)
          path = File.join(root, name)
          FileUtils.mkdir_p(path, mode: 0o755)
          path
        end
      end

      # Removes this process's folders (the chroots of finished builds are
      # gone already: sbuild removes them).
      def close
        @lock.synchronize do
          FileUtils.rm_rf([@root, @disk].compact)
          @root = @disk = nil
        end
      end

      # Enough bytes free on the tmpfs and available in memory for a build.
      def room?
        return false unless File.directory?(@shm) && File.writable?(@shm)

        free = @free_bytes.call(@shm)
        available = UnpackDir.available_memory(@meminfo)
        !free.nil? && !available.nil? && free >= @needed && available >= @needed
      end

      private

      # The config file in this process's folder, one per content and named
      # by it: a build's chroot goes to tmpfs or not as the room is at its
      # start, and the lines differ per target (AptCache's folder), so a
      # build never reads a file another build is writing.
      def config(on_tmpfs, extra)
        @lock.synchronize do
          @root ||= make_root
          lines = on_tmpfs ? ["$unshare_tmpdir_template = '#{@root}/chroot.XXXXXXXXXX';"] : []
          text = [*lines, *extra, "1;"].join("\n") << "\n"
          path = File.join(@root, "sbuild-#{Digest::SHA256.hexdigest(text)[0, 16]}.conf")
          File.write(path, text) unless File.file?(path)
          path
        end
      end

      # This process's folder: on tmpfs, else (no tmpfs to write to, but
      # lines to say) a temporary folder of its own.
      def make_root
        return Dir.mktmpdir("relspec-sbuild") unless File.directory?(@shm) && File.writable?(@shm)

        Temporaries.sweep(@shm)
        root = Temporaries.path(@shm, "sbuild")
        # sbuild's namespace root (a subordinate uid) makes the chroot
        # folder inside and must reach it
        FileUtils.mkdir(root, mode: 0o755)
        root
      end

      # This process's folder on disk, beside what killed runs left there.
      def make_disk_root
        Temporaries.sweep(Dir.tmpdir)
        root = Temporaries.path(Dir.tmpdir, "sbuild-disk")
        # sbuild's namespace root reaches the chroot's layers through it
        FileUtils.mkdir(root, mode: 0o755)
        root
      end
    end
  end
end
