# frozen_string_literal: true

require "digest"
require_relative "../apt/dependency"

module Relspec
  module Plan
    # What planning reads of a distribution's Packages index: the version of
    # each package and the versions packages provide with "=" (Ruby's
    # default gems: "Provides: ruby-date (= 3.2.2)"). Kept in the apt cache
    # under the index's SHA256 (which the Release file gives without reading
    # the index), so that a plan reads ~1.5 MB of names and versions instead
    # of parsing Debian's whole main index (~90 MB, 4-8 s) every time.
    # Writer (#dump) and reader (.load) of that cache entry are both here.
    class ArchiveVersions
      CACHE_ENTRY = "archive-versions"
      SEPARATOR = "--- provided ---"

      # The versions of the +target+'s +component+ in +repository+ (an
      # Apt::Repository or Apt::HostLists), from +cache+ (Apt::Cache) when
      # it has them. Raises what +repository+ raises.
      def self.of(repository, target, component, cache)
        digest = repository.index_digest(target.codename, target.arch, component: component)
        cached = load(cache.read(digest, CACHE_ENTRY))
        return cached if cached

        versions = from_index(repository.packages(target.codename, target.arch, component: component))
        cache.write(digest, CACHE_ENTRY, versions.dump)
        versions
      end

      # From an Apt::PackageIndex.
      def self.from_index(index)
        provided = index.names.flat_map do |package|
          field = index[package].provides
          next [] unless field&.include?("=")

          relations(field).select { |relation| relation.operator == "=" }.map { |relation| [relation.name, relation.version] }
        end
        new(index.names.to_h { |name| [name, index[name].version] }, provided)
      end

      # A Provides field this reader cannot parse provides nothing.
      def self.relations(field)
        Apt::Dependency.parse(field).flatten
      rescue ArgumentError
        []
      end
      private_class_method :relations

      # The versions #dump wrote, or nil when +text+ is not that (missing,
      # or changed since: its first line is the SHA256 of the rest).
      def self.load(text)
        sha256, body = text&.b&.force_encoding(Encoding::UTF_8)&.split("\n", 2)
        return nil unless body && Digest::SHA256.hexdigest(body) == sha256

        packages, provided = body.split("#{SEPARATOR}\n", 2)
        new(pairs(packages).to_h, pairs(provided.to_s))
      end

      def self.pairs(lines)
        lines.split("\n").map { |line| line.split(" ", 2) }
      end
      private_class_method :pairs

      # +packages+: name => version; +provided+: [name, version] in the
      # index's order.
      def initialize(packages, provided)
        @packages = packages.freeze
        @provided = provided.freeze
        freeze
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
               "#{@provided.map { |name, version| "#{name} #{version}\n" }.join}"
        "#{Digest::SHA256.hexdigest(body)}\n#{body}"
      end
    end
  end
end
