# frozen_string_literal: true

require "digest"

module Relspec
  module Debian
    # The stamp of an emitted source package folder: the digest of its
    # inputs, then the name, size and SHA256 of every file written. A later
    # compile trusts the folder only if the inputs are the same and the files
    # still are what the stamp vouches for: sizes are always compared (a
    # truncated .orig.tar.gz is noticed), digests only of files changed since
    # the stamp was written, so an unchanged tree costs one stat per file.
    # No mtime goes into the stamp: the output stays byte-identical.
    class Emitted
      def initialize(dir, stamp_name)
        @dir = dir
        @path = File.join(dir, stamp_name)
        @stamp_name = stamp_name
      end

      # Writes the stamp for +inputs+ over the files now in the folder.
      def record(inputs)
        lines = Dir.children(@dir).reject { |name| name == @stamp_name }.sort.map do |name|
          file = File.join(@dir, name)
          "#{name} #{File.size(file)} #{Digest::SHA256.file(file).hexdigest}\n"
        end
        File.write(@path, "#{inputs}\n#{lines.join}")
      end

      def vouches_for?(inputs, required)
        first, *files = File.read(@path).lines.map(&:split)
        return false unless first == [inputs] && files.any? { |name, _, _| name == required }

        stamped_at = File.mtime(@path)
        files.all? { |name, size, sha256| intact?(File.join(@dir, name), Integer(size), sha256, stamped_at) }
      rescue SystemCallError, ArgumentError, TypeError
        false
      end

      private

      def intact?(file, size, sha256, stamped_at)
        stat = File.stat(file)
        return false unless stat.file? && stat.size == size

        stat.mtime <= stamped_at || Digest::SHA256.file(file).hexdigest == sha256
      end
    end
  end
end
