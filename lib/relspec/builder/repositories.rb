# frozen_string_literal: true

require_relative "request"

module Relspec
  module Builder
    # The apt repositories a release's builds take build-dependencies from:
    # the release's own repository and every ancestor's, in search order, as
    # their specs (or `external:` entries) declare them. Relative paths are
    # relative to the declaring spec's folder; a local path is preferred
    # when it exists, as when planning.
    module Repositories
      module_function

      def of(resolution, codename)
        own = [[resolution.effective.release, resolution.effective["repository"], resolution.spec_file.path]]
        ancestors = resolution.hierarchy.ancestors.map do |node|
          if node.external?
            release = node.source
            [release.name, %w[path url keyring trusted].to_h { |key| [key, release.value(key)] }.compact,
             release.declared_in.path]
          else
            spec = ReleaseSpec::Resolution.new(resolution.hierarchy.library, node.source)
            [spec.effective.release, spec.effective["repository"], node.source.path]
          end
        end
        (own + ancestors).filter_map { |name, entry, file| repository(name, entry, File.dirname(file), codename) }
      end

      def repository(name, entry, base, codename)
        return nil unless entry.is_a?(Hash)

        path = entry["path"] && File.expand_path(entry["path"], base)
        uri = path && (File.directory?(path) || !entry["url"]) ? path : entry["url"]
        return nil unless uri

        Repository.new(name: name, uri: uri, suite: codename, components: ["main"],
                       keyring: entry["keyring"] && File.expand_path(entry["keyring"], base),
                       trusted: entry["trusted"] == true)
      end
    end
  end
end
