# frozen_string_literal: true

require_relative "snapshot_source"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  class Catalog
    # Chooses how to read a spec's `workspace:`: a catalog snapshot file
    # (.yml) or an autoproj workspace folder. autoproj is loaded only for the
    # latter, and then only in a child process.
    module Source
      module_function

      # +distributions+: codename => ReleaseSpec::Distribution the OS dependencies
      # must be known for.
      # +cache+: a Catalog::Cache for workspaces (nil: always load).
      # +manifests+: name => manifest.xml text read instead of the checkout's.
      def load(path, distributions, cache: nil, manifests: {})
        if SnapshotSource.snapshot?(path)
          catalog = SnapshotSource.load(path)
          check_codenames(path, catalog, distributions.keys)
          catalog
        else
          require_relative "autoproj_source"
          return AutoprojSource.load(path, distributions, manifests: manifests) unless cache

          cache.fetch(path, distributions, manifests) { AutoprojSource.load(path, distributions, manifests: manifests) }
        end
      end

      def check_codenames(path, catalog, codenames)
        missing = codenames - catalog.codenames
        return if missing.empty?

        raise InvalidInput, [Diagnostic.error("catalog-targets",
                                              "the catalog snapshot has no OS dependencies for #{missing.join(', ')}",
                                              location: Location.file_only(path),
                                              hint: "export it again with --targets #{(catalog.codenames | codenames).join(',')}")]
      end
    end
  end
end
