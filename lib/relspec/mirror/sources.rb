# frozen_string_literal: true

require_relative "binary_index"
require_relative "../osdeps/reader"
require_relative "../osdeps/operating_system"
require_relative "../apt/fetcher"
require_relative "../apt/host_lists"
require_relative "../apt/opening"

module Relspec
  module Mirror
    # What one target of a release is mirrored from: the release's own
    # repository, its ancestors' and the distribution's archive (the spec's
    # `distributions.<codename>.archive`: a repository, or this machine's apt
    # lists with `host: true`, whose -updates and -security suites count
    # too). All read through relspec's verified readers (Release checksums,
    # keyrings), then as one BinaryIndex.
    class Sources
      # +index+: BinaryIndex of everything; +seeds+: the names the release
      # holds (its repository's packages and the names of its osdeps file,
      # the inherited ones among them); +required+: the distribution's
      # Essential and Priority required packages; +ancestors+: their names.
      Read = Struct.new(:index, :seeds, :required, :ancestors, keyword_init: true)

      def initialize(resolution, timeout: 10, cache: Apt::Cache.new(nil))
        @resolution = resolution
        @effective = resolution.effective
        @fetcher_options = { timeout: timeout }
        @cache = cache
        @spec_dir = File.dirname(resolution.spec_file.path)
      end

      def read(target)
        index = BinaryIndex.new
        seeds = release(index, target)
        ancestors = @resolution.lineage.opened_ancestors(fetcher_options: @fetcher_options, cache: @cache)
        ancestors.each { |ancestor| repository_into(index, ancestor.repository, ancestor.name, target, optional: true) }
        required = distribution(index, target)
        Read.new(index: index, seeds: seeds, required: required, ancestors: ancestors.map(&:name)).freeze
      end

      private

      def release(index, target)
        entry = @effective.repository
        unless entry
          raise InvalidInput, [Diagnostic.error("mirror-repository", "release #{@effective.release} has no repository " \
                                                                     "to mirror", location: @resolution.spec_file.location(["release"]))]
        end

        reader = Apt::Opening.repository(entry, entry.location, fetcher_options: @fetcher_options, cache: @cache)
        names = repository_into(index, reader, @effective.release, target, optional: false)
        (names + osdeps_names(reader, target)).uniq.sort
      end

      # The binaries of +reader+'s index for +target+ into +index+; their
      # names. A release that was never published for the target is an error
      # for the release itself, nothing for an ancestor built elsewhere.
      def repository_into(index, reader, name, target, optional:)
        return [] unless reader

        text = reader.packages_text(target.codename, target.arch)
        own = BinaryIndex.new.add(text, origin: Origin.new(label: name, fetcher: reader.fetcher, distribution: false),
                                        where: "#{reader.url} (#{target.codename}/main/binary-#{target.arch})")
        index.merge(own)
        own.names
      rescue Apt::Repository::Missing => e
        return [] if optional

        raise RepositoryError, "#{e.message} (publish the release for #{target} before mirroring it)"
      end

      # The Debian names of the release's osdeps file for the target
      # (published beside the repository): inherited packages are in it
      # although the release's own index does not hold them. Read as
      # autoproj on the target's system reads it (Osdeps::Reader), so an
      # Ubuntu release's entries ("ubuntu,debian") count as a Debian one's.
      def osdeps_names(reader, target)
        path = "osdeps/#{@effective.release}-#{target.arch}.yml"
        bytes = reader.fetcher.fetch(path, max_bytes: 16 * 1024 * 1024)
        return [] unless bytes

        system = Osdeps::OperatingSystem.new(@effective.distributions.fetch(target.codename).osdeps_type_key.split(","),
                                             [target.codename])
        read = Osdeps::Reader.yaml(bytes)
        read = Osdeps::Reader.resolve(read.value, system) if read.ok?
        raise RepositoryError, "#{reader.fetcher.url_of(path)}: #{read.reason}" unless read.ok?

        read.value.values
      end

      def distribution(index, target)
        distribution = @effective.distributions.fetch(target.codename)
        archive = distribution.archive
        unless archive
          raise InvalidInput, [Diagnostic.error("mirror-archive", "distributions.#{target.codename} has no archive to " \
                                                                  "mirror from", location: @resolution.spec_file.location(["release"]),
                                                                                 hint: "set distributions.#{target.codename}.archive " \
                                                                                       "(host: true for this machine's apt lists)")]
        end

        archive.host? ? host_into(index, target) : archive_into(index, archive, target)
        index.binaries.select { |binary| binary.required? && binary.origin.distribution }.map(&:name).sort
      end

      def host_into(index, target)
        Apt::HostLists.new.suite_indices(target.codename, target.arch).each do |listed, text|
          fetcher = Apt::Fetcher.new(listed.repo_uri, **@fetcher_options)
          index.add(text, origin: Origin.new(label: listed.suite, fetcher: fetcher, distribution: true),
                          where: "#{listed.repo_uri} (#{listed.suite}/#{listed.component}/binary-#{listed.arch})")
        end
      end

      # Each component's index of the target's architecture and its
      # binary-all where apt reads one (Repository#index_architectures).
      def archive_into(index, archive, target)
        reader = Apt::Opening.archive(archive, @spec_dir, fetcher_options: @fetcher_options, cache: @cache)
        archive.read_components.each do |component|
          reader.index_architectures(target.codename, target.arch, component: component).each do |arch|
            text = reader.packages_text(target.codename, arch, component: component)
            index.add(text, origin: Origin.new(label: target.codename, fetcher: reader.fetcher, distribution: true),
                            where: "#{reader.url} (#{target.codename}/#{component}/binary-#{arch})")
          end
        end
      end
    end
  end
end
