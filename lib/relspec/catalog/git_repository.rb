# frozen_string_literal: true

require "zlib"

module Relspec
  class Catalog
    # Reads HEAD's commit id and commit time straight from a checkout's .git
    # folder: refs, packed-refs, loose objects and pack files (index v2).
    #
    # A catalog needs this for every package, and starting one git process
    # per checkout costs more than autoproj's whole load on large workspaces.
    # Anything this reader does not handle (deltified commits, worktrees,
    # reftables) returns nil and the caller asks git itself.
    class GitRepository
      COMMIT_TYPE = 1
      PACK_SIGNATURE = "\xfftOc".b

      def initialize(checkout)
        @git_dir = File.join(checkout, ".git")
      end

      # [commit id, committer time in seconds] of HEAD, or nil.
      def head
        commit = resolve(File.read(File.join(@git_dir, "HEAD")).strip)
        return nil unless commit

        seconds = committer_time(read_commit(commit))
        seconds && [commit, seconds]
      rescue SystemCallError, Zlib::Error
        nil
      end

      private

      def resolve(reference, depth = 0)
        return reference if reference.match?(/\A\h{40}\z/)
        return nil unless (name = reference[/\Aref: (\S+)\z/, 1]) && depth < 5

        path = File.join(@git_dir, name)
        return resolve(File.read(path).strip, depth + 1) if File.file?(path)

        packed_ref(name)
      end

      def packed_ref(name)
        path = File.join(@git_dir, "packed-refs")
        return nil unless File.file?(path)

        File.foreach(path) do |line|
          sha, ref = line.split
          return sha if ref == name && sha.match?(/\A\h{40}\z/)
        end
        nil
      end

      def read_commit(sha)
        loose = File.join(@git_dir, "objects", sha[0, 2], sha[2..])
        if File.file?(loose)
          raw = Zlib::Inflate.inflate(File.binread(loose))
          header, body = raw.split("\0", 2)
          return header.start_with?("commit ") ? body : nil
        end
        Dir.glob(File.join(@git_dir, "objects", "pack", "*.idx")).each do |index|
          offset = pack_offset(index, [sha].pack("H*"))
          return packed_commit(index.sub(/\.idx\z/, ".pack"), offset) if offset
        end
        nil
      end

      # Binary search in a version 2 pack index.
      def pack_offset(index_path, binary_sha)
        index = File.binread(index_path)
        return nil unless index.byteslice(0, 8) == "#{PACK_SIGNATURE}\x00\x00\x00\x02".b

        first = binary_sha.getbyte(0)
        low = first.zero? ? 0 : index.byteslice(8 + ((first - 1) * 4), 4).unpack1("N")
        high = index.byteslice(8 + (first * 4), 4).unpack1("N")
        count = index.byteslice(8 + (255 * 4), 4).unpack1("N")
        names = 8 + (256 * 4)
        while low < high
          middle = (low + high) / 2
          case index.byteslice(names + (middle * 20), 20) <=> binary_sha
          when 0 then return offset_at(index, names + (count * 24), count, middle)
          when -1 then low = middle + 1
          else high = middle
          end
        end
        nil
      end

      def offset_at(index, offsets, count, position)
        offset = index.byteslice(offsets + (position * 4), 4).unpack1("N")
        return offset if offset.nobits?(0x80000000)

        index.byteslice(offsets + (count * 4) + ((offset & 0x7fffffff) * 8), 8).unpack1("Q>")
      end

      def packed_commit(pack_path, offset)
        File.open(pack_path, "rb") do |pack|
          pack.seek(offset)
          byte = pack.readbyte
          return nil unless ((byte >> 4) & 7) == COMMIT_TYPE

          byte = pack.readbyte while byte.anybits?(0x80)
          inflater = Zlib::Inflate.new
          body = +""
          body << inflater.inflate(pack.read(4096)) until inflater.finished?
          body
        ensure
          inflater&.close
        end
      end

      def committer_time(body)
        body && body[/^committer .*> (\d+) [+-]\d{4}$/, 1]&.to_i
      end
    end
  end
end
