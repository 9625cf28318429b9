# frozen_string_literal: true

require_relative "../apt/packages_scanner"
require_relative "../apt/version"
require_relative "../apt/dependency"
require_relative "../error"
require_relative "../osdeps/trust"

module Relspec
  module Mirror
    # Where a binary package's file is read from: a fetcher (a repository's
    # base folder or URL, Apt::Fetcher), how reports name it, and whether it
    # is the distribution's archive (not a release's repository).
    Origin = Struct.new(:label, :fetcher, :distribution, keyword_init: true)

    # One binary package of an index, with what a mirror needs: its
    # relationships (for the closure), its file and the checksum the signed
    # index gives for it (for the download), and whether a minimal system
    # of the distribution needs it.
    Binary = Struct.new(:name, :version, :architecture, :depends, :provides, :filename, :sha256, :size, :essential,
                        :priority, :origin, keyword_init: true) do
      def required?
        essential || priority == "required"
      end

      def file_name
        File.basename(filename)
      end

      def to_s
        "#{name} #{version}"
      end
    end

    # The binary packages of some Packages indices, read as untrusted data:
    # a name, version, file name or checksum that is not what it must be
    # stops the reading, naming the index and the stanza, before anything
    # reaches a path, a download or reprepro. Several indices (a suite and
    # its -updates and -security) merge: the highest version of a name wins,
    # except that a release's package (its own or an ancestor's repository)
    # is never replaced by the distribution's: the mirror is of the release
    # as it was published, and the pin is said (#pinned).
    class BinaryIndex
      # The release's package +kept+ over the distribution's higher
      # version +shadowed+ of the same name.
      Pin = Struct.new(:kept, :shadowed, keyword_init: true)

      FIELDS = %w[Package Version Architecture Depends Pre-Depends Provides Filename SHA256 Size Essential
                  Priority].freeze
      # pool paths as archives write them: no "..", no absolute path, no
      # characters a shell or reprepro would read otherwise
      FILENAME = %r{\A(?!/)(?!.*(?:\A|/)\.\.?(?:/|\z))[A-Za-z0-9._+~%/-]+\.u?deb\z}
      SHA256 = /\A\h{64}\z/

      # An index that is not what it seems.
      class Invalid < Relspec::RepositoryError; end

      def initialize
        @binaries = {}
        @pins = {}
        @providers_map = nil
      end

      # Adds the stanzas of +text+ (uncompressed Packages) read from
      # +origin+; +where+ names the index in messages.
      def add(text, origin:, where:)
        number = 0
        Apt::PackagesScanner.new(text).each(FIELDS) do |stanza|
          number += 1
          keep(binary(stanza, origin, "#{where}, stanza #{number}"))
        end
        @providers_map = nil
        self
      end

      # The binaries of another index into this one.
      def merge(other)
        other.binaries.each { |binary| keep(binary) }
        other.pinned.each { |pin| keep(pin.shadowed) }
        @providers_map = nil
        self
      end

      def [](name)
        @binaries[name]
      end

      def names
        @binaries.keys
      end

      def binaries
        @binaries.values
      end

      # The Pins of the release's packages that the distribution has in a
      # higher version, by name.
      def pinned
        @pins.sort.map(&:last)
      end

      # The binaries that provide +name+ (virtual packages), by name.
      def providers(name)
        providers_map.fetch(name, [])
      end

      private

      def keep(binary)
        known = @binaries[binary.name]
        if known && known.origin.distribution != binary.origin.distribution
          release, distribution = known.origin.distribution ? [binary, known] : [known, binary]
          return pin(release, distribution)
        end
        return if known && !newer?(binary, known)

        @binaries[binary.name] = binary
      end

      # +release+'s package stays whatever the distribution's version; a
      # higher one of the distribution is noted (the highest of its suites).
      def pin(release, distribution)
        @binaries[release.name] = release
        return unless newer?(distribution, release)

        known = @pins[release.name]
        return if known && !newer?(distribution, known.shadowed)

        @pins[release.name] = Pin.new(kept: release, shadowed: distribution).freeze
      end

      def newer?(binary, than)
        Apt::Version.parse(binary.version) > Apt::Version.parse(than.version)
      end

      def providers_map
        @providers_map ||= @binaries.each_value.with_object({}) do |binary, map|
          binary.provides.each { |relation| (map[relation.name] ||= []) << [binary, relation] }
        end
      end

      def binary(stanza, origin, where)
        name = stanza["Package"].to_s
        version = stanza["Version"].to_s
        filename = stanza["Filename"].to_s
        sha256 = stanza["SHA256"].to_s
        size = stanza["Size"].to_s
        reason = Osdeps::Trust.debian_name(name)
        raise Invalid, "#{where}: #{reason}" if reason
        raise Invalid, "#{where} (#{name}): invalid Version #{version.inspect}" unless Apt::Version.valid?(version)
        raise Invalid, "#{where} (#{name}): Filename #{filename.inspect} is not a pool path" unless FILENAME.match?(filename)
        raise Invalid, "#{where} (#{name}): no SHA256 checksum" unless SHA256.match?(sha256)
        raise Invalid, "#{where} (#{name}): Size #{size.inspect} is not a number" unless size.match?(/\A\d{1,12}\z/)

        Binary.new(name: name, version: version, architecture: stanza["Architecture"].to_s.strip,
                   depends: relations(stanza, where, name), provides: parse(stanza["Provides"], where, name).flatten,
                   filename: filename, sha256: sha256.downcase, size: Integer(size, 10),
                   essential: stanza["Essential"].to_s.strip == "yes", priority: stanza["Priority"].to_s.strip,
                   origin: origin).freeze
      end

      # Pre-Depends and Depends: both must be there before the package works.
      def relations(stanza, where, name)
        (parse(stanza["Pre-Depends"], where, name) + parse(stanza["Depends"], where, name)).freeze
      end

      def parse(field, where, name)
        Apt::Dependency.parse(field)
      rescue ArgumentError => e
        raise Invalid, "#{where} (#{name}): #{e.message}"
      end
    end
  end
end
