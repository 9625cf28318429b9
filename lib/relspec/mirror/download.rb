# frozen_string_literal: true

require "digest"
require "fileutils"
require_relative "../apt/fetcher"
require_relative "../error"

module Relspec
  module Mirror
    # The .deb files of binaries, each read from where its index said and
    # checked against that index's Size and SHA256 before it is kept: a
    # mirror never holds bytes its signed indices do not vouch for.
    class Download
      # +dir+: a folder of the mirror's own (made empty, removed by #clean).
      def initialize(dir)
        @dir = dir
      end

      # The local path of each binary's verified file; +progress+ gets
      # (done, total, binary).
      def fetch(binaries, progress: nil)
        FileUtils.rm_rf(@dir)
        FileUtils.mkdir_p(@dir)
        binaries.each_with_index.map do |binary, number|
          progress&.call(number + 1, binaries.size, binary)
          one(binary)
        end
      end

      def clean
        FileUtils.rm_rf(@dir)
      end

      private

      def one(binary)
        bytes = binary.origin.fetcher.fetch(binary.filename, max_bytes: binary.size)
        where = binary.origin.fetcher.url_of(binary.filename)
        raise RepositoryError, "#{where}: missing, although its index lists #{binary}" unless bytes
        unless bytes.bytesize == binary.size && Digest::SHA256.hexdigest(bytes) == binary.sha256
          raise RepositoryError, "#{where}: its size or SHA256 is not what its index says for #{binary} " \
                                 "(the repository changed while it was read, or was tampered with; run again)"
        end

        path = File.join(@dir, binary.file_name)
        File.binwrite(path, bytes)
        path
      rescue Apt::Fetcher::Failure => e
        raise RepositoryError, e.message
      end
    end
  end
end
