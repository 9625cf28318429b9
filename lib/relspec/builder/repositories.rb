# frozen_string_literal: true

require_relative "request"

module Relspec
  module Builder
    # The apt repositories a release's builds take build-dependencies from:
    # the release's own repository and every ancestor's, in search order, as
    # the release's ReleaseSpec::Lineage declares them, found where
    # ReleaseSpec::RepositoryEntry#location says, as when planning.
    module Repositories
      module_function

      def of(lineage, codename)
        lineage.filter_map do |member|
          entry = member.repository
          uri = entry&.location
          next unless uri

          Repository.new(name: member.name, uri: uri, suite: codename, components: ["main"], keyring: entry.keyring,
                         trusted: entry.trusted)
        end
      end
    end
  end
end
