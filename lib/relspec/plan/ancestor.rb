# frozen_string_literal: true

require_relative "../apt/repository"
require_relative "../apt/host_lists"

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
        repository = effective["repository"]
        location = spec_file.key_location(repository ? ["repository"] : ["release"])
        Ancestor.new(name: effective.release, package_prefix: effective["package_prefix"],
                     repository: repository && reader(repository, File.dirname(spec_file.path), fetcher_options, cache),
                     targets: effective.targets, location: location, install_prefix: effective["install_prefix"],
                     separate_prefixes: effective["separate_prefixes"] != false).freeze
      end

      def external(release, fetcher_options, cache)
        entry = %w[path url keyring trusted].to_h { |key| [key, release.value(key)] }.compact
        Ancestor.new(name: release.name, package_prefix: release.value("package_prefix") || "rock",
                     repository: reader(entry, File.dirname(release.declared_in.path), fetcher_options, cache),
                     targets: release.value("targets"), location: release.location,
                     install_prefix: release.value("install_prefix") || "/opt/rock",
                     separate_prefixes: release.value("separate_prefixes") != false).freeze
      end

      # A distribution's archive entry as a reader: this machine's apt lists
      # for `host: true` (Apt::HostLists), else a repository as below.
      def archive_reader(archive, base, fetcher_options, cache)
        return Apt::HostLists.new if archive["host"] == true

        reader(archive, base, fetcher_options, cache)
      end

      # A repository entry ({path, url, keyring, trusted}) as a reader; the
      # local path is preferred when it exists. Relative paths are relative
      # to the spec file's folder.
      def reader(entry, base, fetcher_options, cache)
        path = entry["path"] && File.expand_path(entry["path"], base)
        location = path && (File.directory?(path) || !entry["url"]) ? path : entry["url"]
        keyring = entry["keyring"] && File.expand_path(entry["keyring"], base)
        Apt::Repository.new(Apt::Fetcher.new(location, **fetcher_options), keyring: keyring,
                                                                           trusted: entry["trusted"] == true, cache: cache)
      end
    end
  end
end
