# frozen_string_literal: true

require_relative "../apt/opening"
require_relative "archive_versions"
require_relative "../apt/repository"
require_relative "../apt/version"
require_relative "../catalog/gem_depends"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # The packages a target distribution itself provides, read from its
    # archive (`distributions.<codename>.archive`), limited to the names
    # the plan asks about: a gem of the release is taken from the
    # distribution when it has the gem as ruby-<name> at the same version.
    class DistributionPackages
      # +wanted+: Debian names to look up (or a Regexp they match); +spec_dir+: the folder relative
      # archive paths start from; +location+: where the archives are declared.
      # Targets without an archive get no entries. Raises InvalidInput when
      # an archive cannot be read.
      def self.read(distributions, targets, wanted, spec_dir:, location:, fetcher_options: {}, cache: Apt::Cache.new(nil))
        return new({}, []) if wanted.is_a?(Array) && wanted.empty?

        found = {}
        depends = {}
        problems = []
        gaps = {}
        targets.each do |target|
          archive = distributions.fetch(target.codename).archive
          next unless archive

          repository = Apt::Opening.archive(archive, spec_dir, fetcher_options: fetcher_options, cache: cache)
          found[target], depends[target] = versions(repository, archive, target, wanted, cache)
        rescue Apt::Repository::Missing => e
          # e.g. Ubuntu's arm64 lives on ports.ubuntu.com, not in the amd64 archive
          gaps[target] = e.message
        rescue Apt::Repository::Error => e
          problems << Diagnostic.error("distribution-archive", "the archive of #{target.codename}: #{e.message}",
                                       location: location, hint: "check distributions.#{target.codename}.archive, or the network")
        end
        raise InvalidInput, problems.uniq(&:message) unless problems.empty?

        new(found, targets.reject { |target| found.key?(target) || gaps.key?(target) }, gaps, depends)
      end

      # Every version of each wanted name over the archive's components,
      # newest first, from the packages of that name and from versioned
      # Provides: Ruby's default gems are ruby-<gem> virtual packages of
      # libruby<version> ("Provides: ruby-date (= 3.2.2)" on bookworm), and
      # a real ruby-<gem> may be newer than what libruby provides (minitest:
      # 5.17.0 and libruby3.1's 5.15.0 on bookworm), when a gem's
      # requirement fits the provided one only.
      # Each component's index of the target's architecture, and its
      # binary-all where apt reads one (ruby-<gem> packages are
      # Architecture: all). Returns them, and every gem package's
      # GemDepends (all of them, whatever is wanted: whether a gem is
      # shadowed depends on the packages it reaches).
      def self.versions(repository, archive, target, wanted, cache)
        found = Hash.new { |hash, name| hash[name] = [] }
        depends = {}
        archive.read_components.each do |component|
          repository.index_architectures(target.codename, target.arch, component: component).each do |arch|
            index = ArchiveVersions.of(repository, target, component, cache, arch: arch)
            names = wanted.is_a?(Regexp) ? index.names.grep(wanted) : wanted
            names.each { |name| found[name] << index.version(name) if index.version(name) }
            index.each_provided(wanted) { |name, version| found[name] << version }
            add_depends(depends, index)
          end
        end
        [found.to_h { |name, versions| [name, newest_first(versions)] }, depends.sort.to_h.freeze]
      end
      private_class_method :versions

      # The newest of a name over the components and architectures read.
      def self.add_depends(depends, index)
        index.each_gem_depends do |name, names|
          version = index.version(name)
          known = depends[name]
          next if known && Apt::Version.parse(known.version) >= Apt::Version.parse(version)

          depends[name] = Catalog::GemDepends.new(name: name, version: version, depends: names)
        end
      end
      private_class_method :add_depends

      def self.newest_first(versions)
        versions.uniq.sort_by { |version| Apt::Version.parse(version) }.reverse.freeze
      end
      private_class_method :newest_first

      attr_reader :unknown, :gaps

      # +found+: Target => {name => [versions, newest first]}; +unknown+:
      # targets without an archive; +gaps+: Target => why its archive has
      # nothing for it; +depends+: Target => {gem package name =>
      # Catalog::GemDepends}.
      def initialize(found, unknown, gaps = {}, depends = {})
        @found = found.freeze
        @unknown = unknown.freeze
        @gaps = gaps.freeze
        @depends = depends.freeze
        freeze
      end

      # gem package name => Catalog::GemDepends of the target's archive
      # (the gem packages that depend on any), {} when it was not read.
      def gem_depends(target)
        @depends.fetch(target, {})
      end

      # The newest version of +name+ on +target+, nil when it has none.
      def version_of(name, target)
        versions_of(name, target).first
      end

      # Every version of +name+ the target's archive has (packages and
      # Provides), newest first.
      def versions_of(name, target)
        @found.dig(target, name) || []
      end

      # name => [versions, newest first] of what was looked up in the
      # target's archive, nil when it was not read.
      def index(target)
        @found[target]
      end

      # Whether the target's archive was read (so a name it lacks is known missing).
      def read?(target)
        @found.key?(target)
      end
    end
  end
end
