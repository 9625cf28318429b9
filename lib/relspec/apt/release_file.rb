# frozen_string_literal: true

require "digest"
require_relative "deb822"

module Relspec
  module Apt
    # A repository's dists/<codename>/Release (or the content of InRelease):
    # which architectures and components it has, and the SHA256 and size of
    # every index file, against which downloads are verified.
    class ReleaseFile
      Checksum = Struct.new(:sha256, :size)

      attr_reader :codename, :architectures, :components, :checksums, :sha256

      # +text+: the (verified, unarmored) Release text; +raw+: the bytes as
      # fetched (InRelease or Release), whose digest identifies what was read.
      def self.parse(text, raw: text)
        stanza = Deb822.parse(text).first
        raise Deb822::ParseError.new("the Release file is empty", 1) unless stanza

        new(stanza, Digest::SHA256.hexdigest(raw))
      end

      def initialize(fields, sha256)
        @codename = fields["Codename"] || fields["Suite"]
        @architectures = fields.fetch("Architectures", "").split
        @components = fields.fetch("Components", "").split
        @checksums = parse_checksums(fields["SHA256"])
        @sha256 = sha256
        freeze
      end

      def checksum(path)
        checksums[path]
      end

      private

      def parse_checksums(field)
        return {}.freeze unless field

        field.lines.map(&:strip).reject(&:empty?).to_h do |line|
          sha, size, path = line.split
          [path, Checksum.new(sha, Integer(size)).freeze]
        end.freeze
      end
    end
  end
end
