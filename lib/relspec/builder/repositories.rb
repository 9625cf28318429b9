# frozen_string_literal: true

require_relative "request"

module Relspec
  module Builder
    # The apt repositories a release's builds take build-dependencies from:
    # the release's own repository and every ancestor's, in search order, as
    # their specs (or `external:` entries) declare them, found where
    # ReleaseSpec::RepositoryEntry#location says, as when planning.
    module Repositories
      module_function

      def of(resolution, codename)
        own = [[resolution.effective.release, resolution.effective.repository]]
        ancestors = resolution.hierarchy.ancestors.map do |node|
          if node.external?
            [node.source.name, node.source.repository]
          else
            spec = ReleaseSpec::Resolution.new(resolution.hierarchy.library, node.source)
            [spec.effective.release, spec.effective.repository]
          end
        end
        (own + ancestors).filter_map { |name, entry| repository(name, entry, codename) }
      end

      def repository(name, entry, codename)
        uri = entry&.location
        return nil unless uri

        Repository.new(name: name, uri: uri, suite: codename, components: ["main"], keyring: entry.keyring,
                       trusted: entry.trusted)
      end
    end
  end
end
