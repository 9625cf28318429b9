# frozen_string_literal: true

require_relative "../cache_dir"
require_relative "../cache_writer"

module Relspec
  module Apt
    # Verified index files of remote repositories, kept by the SHA256 of the
    # Release file that listed them: as long as an ancestor's Release file does
    # not change, its indices are never downloaded again.
    #
    # The cache is only ever a shortcut: an entry that is not a regular file
    # (a directory, a FIFO) reads as missing without being opened for long
    # (a FIFO would block), and an entry that cannot be written (a directory
    # in the way, a full file system) is noted once and skipped (CacheWriter).
    class Cache
      # The XDG cache folder (read from the environment, never written to it).
      def self.default_dir
        CacheDir.for("apt")
      end

      # +writer+: the CacheWriter the run's caches share (one note for all).
      def initialize(dir, writer: CacheWriter.new)
        @dir = dir
        @writer = writer
      end

      def read(release_sha256, path)
        return nil unless @dir

        # O_NONBLOCK: opening a FIFO returns at once; fstat then refuses it
        File.open(location(release_sha256, path), File::RDONLY | File::NONBLOCK) do |file|
          file.stat.file? ? file.read.b : nil
        end
      rescue SystemCallError, IOError
        nil
      end

      def write(release_sha256, path, bytes)
        return unless @dir

        @writer.write(location(release_sha256, path), bytes)
        nil
      end

      private

      def location(release_sha256, path)
        File.join(@dir, release_sha256, path.tr("/", "_"))
      end
    end
  end
end
