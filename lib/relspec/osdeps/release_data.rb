# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "../release_specs/names"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../printable"

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
        path = File.join(@dir, "releases.yml")
        index = load_yaml(path, required: false) || {}
        raise InvalidInput, [problem("wrong-type", "releases.yml must map release names to entries", path)] \
          unless index.is_a?(Hash)

        chain = [release]
        while (parent = parent_of(index, chain.first, path))
          raise InvalidInput, [problem("release-cycle", "depends_on cycle through #{parent}", path)] if chain.include?(parent)

          chain.unshift(parent)
        end
        chain
      end

      def parent_of(index, release, path)
        entry = index[release]
        return nil if entry.nil?
        raise InvalidInput, [problem("wrong-type", "the entry of #{release} must be a mapping", path)] unless entry.is_a?(Hash)

        parent = entry["depends_on"]
        return nil if parent.nil?
        return parent if ReleaseSpec::Names.release?(parent)

        raise InvalidInput, [problem("release-name", "#{release} depends_on #{parent.inspect}, which is not a release name", path)]
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

          raise InvalidInput, [problem("missing-osdeps", "no osdeps file #{Printable.text(path)}", path)]
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
