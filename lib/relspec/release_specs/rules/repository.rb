# frozen_string_literal: true

require "uri"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # Where a release's apt repository lives, and how it is trusted: either
      # a keyring verifies its signature, or the spec says `trusted: true`.
      module Repository
        SCHEMES = %w[http https file].freeze

        def self.call(file)
          repository = file.usable("repository")
          repository.is_a?(Hash) ? check(file, ["repository"], repository, "the repository") : []
        end

        def self.check(file, path, repository, what)
          problems = []
          unless repository.key?("path") || repository.key?("url")
            problems << Diagnostic.error("repository-location", "#{what} has neither path nor url",
                                         location: file.location(path),
                                         hint: "set path: (a reprepro base directory) and/or url: (where apt reads it)")
          end
          problems << bad_url(file, path + ["url"], repository["url"]) if repository["url"].is_a?(String)
          if repository["trusted"] == true && repository.key?("keyring")
            problems << Diagnostic.error("repository-trust", "#{what} sets both keyring and trusted: true",
                                         location: file.key_location(path + ["trusted"]),
                                         hint: "a keyring verifies signatures; trusted: true skips that. Keep one")
          end
          problems.compact
        end

        def self.bad_url(file, path, url, example: "https://example.org/rock-releases/master-20.06")
          scheme = URI.parse(url).scheme
          return nil if SCHEMES.include?(scheme)

          Diagnostic.error("repository-url", "url #{url.inspect} is not an http(s) or file URL",
                           location: file.location(path), hint: "write e.g. #{example}")
        rescue URI::InvalidURIError
          Diagnostic.error("repository-url", "url #{url.inspect} is not a valid URL", location: file.location(path))
        end
      end
    end
  end
end
