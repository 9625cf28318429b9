# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Osdeps
    # The osdeps files of a release and its ancestors, as a package set (or
    # relspec's releases/ folder) holds them: releases.yml for the hierarchy
    # (depends_on), <release>-<arch>.yml for each release.
    class ReleaseData
      def initialize(dir)
        @dir = dir
      end

      # Release names from the root of the hierarchy down to +release+.
      def lineage(release)
        index = load_yaml(File.join(@dir, "releases.yml"), required: false) || {}
        chain = [release]
        while (parent = index.dig(chain.first, "depends_on"))
          raise InvalidInput, [problem("release-cycle", "releases.yml: depends_on cycle through #{parent}", "releases.yml")] \
            if chain.include?(parent)

          chain.unshift(parent)
        end
        chain
      end

      # autoproj package => osdeps entry, ancestors first and later releases
      # overriding earlier ones.
      def merged(release, arch)
        lineage(release).each_with_object({}) do |name, merged|
          data = load_yaml(osdeps_file(name, arch), required: name == release)
          merged.merge!(data) if data.is_a?(Hash)
        end
      end

      def osdeps_file(release, arch)
        flat = File.join(@dir, "#{release}-#{arch}.yml")
        File.file?(flat) ? flat : File.join(@dir, release, "osdeps", "#{release}-#{arch}.yml")
      end

      private

      def load_yaml(path, required:)
        unless File.file?(path)
          return nil unless required

          raise InvalidInput, [problem("missing-osdeps", "no osdeps file #{path}", path)]
        end

        document = Yaml::LocatedDocument.load(path)
        raise InvalidInput, document.diagnostics unless document.ok?

        document.data
      end

      def problem(rule, message, path)
        Diagnostic.error(rule, message, location: Location.file_only(path))
      end
    end
  end
end
