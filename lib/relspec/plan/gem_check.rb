# frozen_string_literal: true

require_relative "../debian/package_version"
require_relative "../debian/gem_version"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # A gem version is packaged from one .gem file for good: its orig
    # tarball goes into the repository under the version's name, and a
    # repository never takes a second, different file under that name. So a
    # .gem whose bytes differ from what the lock recorded for the same
    # version (re-published upstream, or another gem_source) is refused.
    module GemCheck
      module_function

      # +locked+: the previous Lock, or nil.
      def call(locked, release_catalog, resolution)
        recorded = locked&.packages || {}
        problems = release_catalog.gems.filter_map do |name, archive|
          before = recorded[name]
          next unless before && before["version"] == Debian::GemVersion.to_debian(archive.version) &&
                      before["commit"] && before["commit"] != archive.sha256

          Diagnostic.error("gem-changed", "gem #{name} #{archive.version} from #{archive.origin} is not the .gem the lock " \
                                          "recorded (SHA256 #{before['commit'][0, 12]}… then, #{archive.sha256[0, 12]}… now)",
                           location: location_of(name, resolution),
                           hint: "a repository cannot take a different orig tarball under the same version: restore " \
                                 "the recorded .gem, or package another version")
        end
        raise InvalidInput, problems unless problems.empty?
      end

      # The gem's `gems:` entry; for a gem packaged without one, gem_source.
      def location_of(name, resolution)
        effective = resolution.effective
        effective.entry_location("gems", name) || effective.origin("gem_source")&.location ||
          resolution.spec_file.location(["gems"])
      end
    end
  end
end
