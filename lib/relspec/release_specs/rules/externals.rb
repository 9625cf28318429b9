# frozen_string_literal: true

require_relative "../names"
require_relative "repository"
require_relative "targets"
require_relative "settings"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # `external:` declares releases that have no spec in specs/ (e.g. built
      # by apaka) so that they can be parents: they need a repository and a name.
      module Externals
        def self.call(file)
          externals = file.usable("external")
          return [] unless externals.is_a?(Hash)

          externals.flat_map do |name, entry|
            path = ["external", name]
            next [] unless entry.is_a?(Hash)

            problems = []
            unless Names.release?(name)
              problems << Diagnostic.error("release-name", "invalid external release name #{name.inspect}",
                                           location: file.key_location(path),
                                           hint: Names::RELEASE_HINT)
            end
            problems.concat(Repository.check(file, path, entry, "external release #{name}"))
            problems.concat(Targets.check(file, path + ["targets"], entry["targets"]))
            prefix = entry["package_prefix"]
            problems << Settings.debian_prefix(file, path + ["package_prefix"], prefix) if prefix.is_a?(String)
            problems.compact
          end
        end
      end
    end
  end
end
