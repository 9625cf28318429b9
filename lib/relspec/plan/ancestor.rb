# frozen_string_literal: true

require_relative "../apt/repository"
require_relative "../apt/host_lists"
require_relative "../release_specs/values/repository_entry"

module Relspec
  module Plan
    # A release this one may take packages from: its name, the prefix of its
    # Debian names, its apt repository and the targets it was built for
    # (nil: unknown, every target is tried, as for external releases without
    # `targets:`). +location+ says where its repository is declared.
    Ancestor = Struct.new(:name, :package_prefix, :repository, :targets, :location, :install_prefix, :separate_prefixes,
                          keyword_init: true) do
      def target?(target)
        targets.nil? || Array(targets[target.codename]).include?(target.arch)
      end
    end

    # Builds the Ancestors of a release from its spec hierarchy.
    module Ancestors
      module_function

      # +resolution+: the release's ReleaseSpec::Resolution; +fetcher_options+ go to
      # every Apt::Fetcher (timeout), +cache+ is the Apt::Cache.
      def of(resolution, fetcher_options: {}, cache: Apt::Cache.new(nil))
        resolution.hierarchy.ancestors.map do |node|
          if node.external?
            external(node.source, fetcher_options, cache)
          else
            declared(ReleaseSpec::Resolution.new(resolution.hierarchy.library, node.source), fetcher_options, cache)
          end
        end
      end

      def declared(resolution, fetcher_options, cache)
        effective = resolution.effective
        spec_file = resolution.spec_file
        repository = effective.repository
        location = spec_file.key_location(repository ? ["repository"] : ["release"])
        prefixes = effective.prefixes
        Ancestor.new(name: effective.release, package_prefix: prefixes.package_prefix,
                     repository: repository && reader(repository, repository.location, fetcher_options, cache),
                     targets: effective.targets, location: location, install_prefix: prefixes.install_prefix,
                     separate_prefixes: prefixes.separate_prefixes).freeze
      end

      def external(release, fetcher_options, cache)
        repository = release.repository
        prefixes = release.prefixes
        Ancestor.new(name: release.name, package_prefix: prefixes.package_prefix,
                     repository: reader(repository, repository.location, fetcher_options, cache),
                     targets: release.value("targets"), location: release.location,
                     install_prefix: prefixes.install_prefix, separate_prefixes: prefixes.separate_prefixes).freeze
      end

      # A distribution's archive entry as a reader: this machine's apt lists
      # for `host: true` (Apt::HostLists), else a repository as below.
      def archive_reader(archive, base, fetcher_options, cache)
        return Apt::HostLists.new if archive.host?

        entry = archive.repository_entry(base)
        reader(entry, entry.location, fetcher_options, cache)
      end

      # A ReleaseSpec::RepositoryEntry read at +location+ (one of its
      # locations) as an Apt::Repository.
      def reader(entry, location, fetcher_options, cache)
        Apt::Repository.new(Apt::Fetcher.new(location, **fetcher_options), keyring: entry.keyring,
                                                                           trusted: entry.trusted, cache: cache)
      end
    end
  end
end
