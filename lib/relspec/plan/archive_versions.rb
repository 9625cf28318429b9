# frozen_string_literal: true

require "digest"
require_relative "../apt/dependency"
require_relative "../debian/naming"

module Relspec
  module Plan
    # What planning reads of a distribution's Packages index: the version of
    # each package and the versions packages provide with "=" (Ruby's
    # default gems: "Provides: ruby-date (= 3.2.2)"), and which gem packages
    # each gem package depends on (ruby-dry-types: ruby-dry-core, …; the
    # names Naming::DISTRIBUTION_GEMS matches, a few thousand lines): a
    # distribution gem the release's own gems would shadow is known by
    # them (Catalog::ShadowedGems). Kept in the apt cache
    # under the SHA256 of the index file that is read (the compressed file,
    # checked against the Release file), so that a plan reads ~1.5 MB of
    # names and versions instead of parsing Debian's whole main index
    # (~90 MB, 4-8 s) every time. Writer (#dump) and reader (.load) of that
    # cache entry are both here. The entry is untrusted: every line is
    # checked, and an entry with one bad line is made again from the index.
    class ArchiveVersions
      # -2: with the gem depends; an older relspec sharing the cache keeps
      # its own entry rather than each making the other's again
      CACHE_ENTRY = "archive-versions-2"
      SEPARATOR = "--- provided ---"
      DEPENDS_SEPARATOR = "--- gem depends ---"
      # What a line of the entry can hold: a name without spaces or control
      # characters (Debian's names are [a-z0-9+.-]; an index may hold
      # anything) and a version dpkg accepts: exactly Apt::Version.valid?
      # (its VALID, and no empty revision after a trailing "-"), written as
      # one pattern so that a whole section of 60,000 lines is checked in
      # one match (a check per line took four times as long as the reading).
      NAME = /[^\s\p{Cc}]+/
      VERSION = /(?:\d+:[0-9](?:[A-Za-z0-9.+~:-]*[A-Za-z0-9.+~:])?|[0-9](?:[A-Za-z0-9.+~-]*[A-Za-z0-9.+~])?)/
      LINES = /\A(?:#{NAME} #{VERSION}\n)*\z/
      PAIR = /\A#{NAME} #{VERSION}\n\z/
      # a gem package and the gem packages it depends on
      DEPENDS_LINES = /\A(?:#{NAME}(?: #{NAME})+\n)*\z/

      # The versions of the +target+'s +component+ in +repository+ (an
      # Apt::Repository or Apt::HostLists), from +cache+ (Apt::Cache) when
      # it has them; +arch+: the index read (the target's, or "all").
      # Raises what +repository+ raises.
      def self.of(repository, target, component, cache, arch: target.arch)
        digest = repository.index_digest(target.codename, arch, component: component)
        cached = load(cache.read(digest, CACHE_ENTRY))
        return cached if cached

        versions = from_index(repository.packages(target.codename, arch, component: component))
        cache.write(digest, CACHE_ENTRY, versions.dump)
        versions
      end

      # From an Apt::PackageIndex. A name no Debian package can have (a
      # space, a control character) names nothing a plan asks for and could
      # not be written as a line of the entry: it is left out.
      def self.from_index(index)
        provided = index.names.flat_map do |package|
          field = index[package].provides
          next [] unless field&.include?("=")

          relations(field).select { |relation| relation.operator == "=" }.map { |relation| [relation.name, relation.version] }
        end
        packages = index.names.map { |name| [name, index[name].version] }.select { |pair| entry?(pair) }.to_h
        new(packages, provided.select { |pair| entry?(pair) }, gem_depends(index, packages))
      end

      # name => the gem packages its Depends name (every alternative), for
      # the gem packages of +packages+ that depend on any.
      def self.gem_depends(index, packages)
        packages.keys.grep(Debian::Naming::DISTRIBUTION_GEMS).sort.filter_map do |name|
          field = index[name].depends
          names = field ? relations(field).map(&:name).grep(Debian::Naming::DISTRIBUTION_GEMS) : []
          names = names.uniq.sort.select { |other| entry?([other, "0"]) }
          [name, names.freeze] unless names.empty?
        end.to_h
      end
      private_class_method :gem_depends

      # Whether [name, version] can be a line of the entry.
      def self.entry?(pair)
        name, version = pair
        !version.nil? && PAIR.match?("#{name} #{version}\n")
      end

      # A Provides field this reader cannot parse provides nothing.
      def self.relations(field)
        Apt::Dependency.parse(field).flatten
      rescue ArgumentError
        []
      end
      private_class_method :relations

      # The versions #dump wrote, or nil when +text+ is not that: missing,
      # changed since (its first line is the SHA256 of the rest), or with a
      # line that is not a name and a valid version.
      def self.load(text)
        text = text&.b&.force_encoding(Encoding::UTF_8)
        return nil unless text&.valid_encoding?

        sha256, body = text.split("\n", 2)
        return nil unless body && Digest::SHA256.hexdigest(body) == sha256

        packages, rest = body.split("#{SEPARATOR}\n", 2)
        # an entry written before the gem depends were kept is made again
        provided, depends = rest&.split("#{DEPENDS_SEPARATOR}\n", 2)
        return nil unless depends && DEPENDS_LINES.match?(depends)

        packages = pairs(packages)
        provided = pairs(provided)
        return nil unless packages && provided

        new(packages.to_h, provided, depends.split("\n").to_h { |line| line.split.then { |name, *names| [name, names.freeze] } })
      end

      # The [name, version] of each line, or nil when one is not that.
      def self.pairs(lines)
        return nil unless LINES.match?(lines)

        lines.split("\n").map { |line| line.split(" ", 2) }
      end
      private_class_method :pairs

      # +packages+: name => version; +provided+: [name, version] in the
      # index's order; +gem_depends+: gem package name => the gem packages
      # it depends on.
      def initialize(packages, provided, gem_depends = {})
        @packages = packages.freeze
        @provided = provided.freeze
        @gem_depends = gem_depends.freeze
        freeze
      end

      # The gem packages (names Naming::DISTRIBUTION_GEMS matches) gem
      # package +name+ depends on, [] for none.
      def gem_depends(name)
        @gem_depends.fetch(name, [])
      end

      # Yields each gem package that depends on gem packages, with their names.
      def each_gem_depends(&)
        @gem_depends.each(&)
      end

      def names
        @packages.keys
      end

      def version(name)
        @packages[name]
      end

      # Yields name and version of each "=" Provides whose name is +wanted+
      # (names, or a Regexp).
      def each_provided(wanted)
        @provided.each do |name, version|
          yield name, version if wanted.is_a?(Regexp) ? wanted.match?(name) : wanted.include?(name)
        end
      end

      def dump
        body = "#{@packages.map { |name, version| "#{name} #{version}\n" }.join}#{SEPARATOR}\n" \
               "#{@provided.map { |name, version| "#{name} #{version}\n" }.join}#{DEPENDS_SEPARATOR}\n" \
               "#{@gem_depends.map { |name, names| "#{[name, *names].join(' ')}\n" }.join}"
        "#{Digest::SHA256.hexdigest(body)}\n#{body}"
      end
    end
  end
end
