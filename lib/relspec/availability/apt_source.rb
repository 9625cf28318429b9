# frozen_string_literal: true

require_relative "../apt/repository"
require_relative "../apt/cache"
require_relative "index_names"
require_relative "hint"

module Relspec
  module Availability
    # Availability from a distribution's apt archive (or this machine's
    # lists): the Packages indices of `<codename>`, `<codename>-updates` and
    # `<codename>-security`, every configured component, the target's
    # architecture and `all` where apt reads a binary-all there
    # (Repository#index_architectures).
    # The suites after the first are optional (Debian keeps -security in
    # another archive). Read with the same reader as ancestors (checksums,
    # signatures); the names of each index are cached by the index's SHA256
    # from the Release file, so an unchanged archive is never parsed twice.
    class AptSource
      SUITES = ["", "-updates", "-security"].freeze

      # A target this archive cannot answer for (no such codename or
      # architecture); the message says why.
      class Unavailable < StandardError; end

      # +reader+: Apt::Repository or Apt::HostLists; +names_cache+: an
      # Apt::Cache (its folder: relspec's availability cache).
      def initialize(reader, components, names_cache: Apt::Cache.new(nil))
        @reader = reader
        @components = components
        @names_cache = names_cache
        @targets = {}
      end

      def describe
        "apt: #{@reader.url}"
      end

      # {target => [{name => true/false/nil}, problem or nil]} for the
      # +wanted+ names of each target (nil: not known, the problem says why).
      def lookup_many(wanted)
        wanted.to_h do |target, names|
          [target, [lookup(target, names), nil]]
        rescue Unavailable, Apt::Repository::Error => e
          [target, [names.to_h { |name| [name, nil] }, e.message]]
        end
      end

      # {name => true/false} for the +names+ on +target+ (true also when a
      # package provides the name). Raises Unavailable or Apt::Repository::Error.
      def lookup(target, names)
        indices = names_of(target)
        names.to_h { |name| [name, indices.any? { |index| index.lookup(name) }] }
      end

      def hint(target, name)
        (@hints ||= {})[target] ||= Hint.new(names_of(target).flat_map(&:names).uniq)
        @hints[target].for(name)
      end

      private

      def names_of(target)
        @targets[target] ||= SUITES.flat_map { |suffix| suite_names(target, suffix) }
      end

      def suite_names(target, suffix)
        suite = "#{target.codename}#{suffix}"
        @components.flat_map do |component|
          @reader.index_architectures(suite, target.arch, component: component).filter_map do |arch|
            index_names(suite, arch, component)
          rescue Apt::Repository::Missing => e
            raise Unavailable, e.message if suffix.empty? && arch == target.arch

            nil
          end
        end
      rescue Apt::Repository::Missing => e
        # no such suite: -updates and -security are optional
        raise Unavailable, e.message if suffix.empty?

        []
      end

      # The cache entry's name says its format: entries written before the
      # names were kept sorted must not be searched by bisection.
      NAMES_ENTRY = "names-sorted"

      def index_names(suite, arch, component)
        digest = @reader.index_digest(suite, arch, component: component)
        cached = @names_cache.read(digest, NAMES_ENTRY)
        return IndexNames.load(cached.force_encoding(Encoding::UTF_8)) if cached

        names = IndexNames.parse(@reader.packages_text(suite, arch, component: component))
        @names_cache.write(digest, NAMES_ENTRY, names.dump)
        names
      end
    end
  end
end
