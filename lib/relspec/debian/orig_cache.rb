# frozen_string_literal: true

require "digest"
require_relative "../temporaries"

module Relspec
  module Debian
    # The cache of orig tarballs (<out>/<release>/.orig/): each tarball is
    # stored with the SHA256 it had when made, and a tarball that no longer
    # has it (a disk filled up, an interrupted copy, a hand edit) is not
    # used: the caller makes it again, instead of failing in tar later.
    module OrigCache
      module_function

      # :intact, :absent (never made, or made by an older relspec without a
      # digest) or :damaged (there, but not the bytes that were stored).
      # Nothing is deleted here: a damaged entry is replaced by store (a
      # rename), so jobs sharing the cache never remove each other's work.
      def state(path)
        return :absent unless File.file?(path) && File.file?(digest_path(path))

        recorded = File.read(digest_path(path)).strip
        Digest::SHA256.file(path).hexdigest == recorded ? :intact : :damaged
      rescue Errno::ENOENT # removed by a concurrent job between the checks
        :absent
      end

      # Moves the finished +temporary+ into the cache as +path+.
      def store(temporary, path)
        digest = Digest::SHA256.file(temporary).hexdigest
        File.rename(temporary, path)
        # one temporary per writer: jobs of two targets may store the same entry
        temporary = Temporaries.path(File.dirname(path), File.basename(digest_path(path)))
        File.write(temporary, "#{digest}\n")
        File.rename(temporary, digest_path(path))
      end

      def digest_path(path)
        "#{path}.sha256"
      end
    end
  end
end
