# frozen_string_literal: true

require "fileutils"
require_relative "../cache_dir"
require_relative "../atomic_file"

module Relspec
  module Apt
    # Verified index files of remote repositories, kept by the SHA256 of the
    # Release file that listed them: as long as an ancestor's Release file does
    # not change, its indices are never downloaded again.
    class Cache
      # The XDG cache folder (read from the environment, never written to it).
      def self.default_dir
        CacheDir.for("apt")
      end

      def initialize(dir)
        @dir = dir
      end

      def read(release_sha256, path)
        return nil unless @dir

        File.binread(location(release_sha256, path))
      rescue SystemCallError
        nil
      end

      def write(release_sha256, path, bytes)
        return unless @dir

        target = location(release_sha256, path)
        FileUtils.mkdir_p(File.dirname(target))
        AtomicFile.write(target, bytes)
      rescue SystemCallError
        nil # a cache that cannot be written is only slower
      end

      private

      def location(release_sha256, path)
        File.join(@dir, release_sha256, path.tr("/", "_"))
      end
    end
  end
end
