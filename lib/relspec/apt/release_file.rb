# frozen_string_literal: true

require "digest"
require "time"
require_relative "deb822"

module Relspec
  module Apt
    # A repository's dists/<codename>/Release (or the content of InRelease):
    # which architectures and components it has, the SHA256 and size of
    # every index file, against which downloads are verified, and how apt
    # reads its indices (Acquire-By-Hash, No-Support-for-Architecture-all).
    class ReleaseFile
      # A SHA256 as the Release file gives it: untrusted text until #valid?
      # says it is 64 lowercase hex digits (only then may it name a by-hash
      # file).
      Checksum = Struct.new(:sha256, :size) do
        def valid?
          sha256.match?(/\A[0-9a-f]{64}\z/)
        end
      end

      # apt's words for yes in a boolean field (StringToBool).
      YES = %w[yes true with on enable 1].freeze

      attr_reader :codename, :suite, :origin, :architectures, :components, :checksums, :sha256, :valid_until

      # +text+: the (verified, unarmored) Release text; +raw+: the bytes as
      # fetched (InRelease or Release), whose digest identifies what was read.
      def self.parse(text, raw: text)
        stanza = Deb822.parse(text).first
        raise Deb822::ParseError.new("the Release file is empty", 1) unless stanza

        new(stanza, Digest::SHA256.hexdigest(raw))
      end

      def initialize(fields, sha256)
        @codename = fields["Codename"] || fields["Suite"]
        @suite = fields["Suite"]
        @origin = fields["Origin"]
        @valid_until = parse_time(fields["Valid-Until"])
        @architectures = fields.fetch("Architectures", "").split
        @components = fields.fetch("Components", "").split
        @checksums = parse_checksums(fields["SHA256"])
        @sha256 = sha256
        @by_hash = YES.include?(fields.fetch("Acquire-By-Hash", "").strip.downcase)
        @no_support_for_all = fields.fetch("No-Support-for-Architecture-all", "").split.freeze
        freeze
      end

      # "Acquire-By-Hash: yes": each index is also served as
      # <its folder>/by-hash/SHA256/<digest>, which a mirror in the middle of
      # an update keeps consistent with this Release file.
      def by_hash?
        @by_hash
      end

      # The architectures whose Packages indices apt reads for +arch+ in
      # +component+: binary-all too where the Release file lists one and has
      # the architecture (Architectures names "all", or names nothing),
      # unless it says "No-Support-for-Architecture-all: Packages" (Debian
      # since 2017: its Architecture: all packages are in every
      # binary-<arch> index, and its binary-all may be stale).
      def package_architectures(arch, component: "main")
        return [arch] if arch == "all" || @no_support_for_all.include?("Packages")
        return [arch] unless architectures.empty? || architectures.include?("all")

        listed = %w[Packages.xz Packages.gz Packages].any? { |name| checksums.key?("#{component}/binary-all/#{name}") }
        listed ? [arch, "all"] : [arch]
      end

      def checksum(path)
        checksums[path]
      end

      # Is this the Release file of distribution +name+? As apt sees it: its
      # Codename or its Suite names it. A signed Release of another
      # distribution served under this name (a replay) is not.
      def describes?(name)
        [codename, suite].compact.include?(name)
      end

      # apt's rule: a Release file whose Valid-Until has passed is refused,
      # however good its signature (an attacker could replay an old one).
      def expired?(now)
        !valid_until.nil? && valid_until < now
      end

      private

      def parse_time(text)
        return nil if text.nil?

        Time.strptime(text.strip, "%a, %d %b %Y %H:%M:%S %z").utc
      rescue ArgumentError
        raise Deb822::ParseError.new("Valid-Until is not a date (#{text.strip})", 1)
      end

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
