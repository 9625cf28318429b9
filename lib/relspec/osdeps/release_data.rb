# frozen_string_literal: true

require_relative "../yaml/located_document"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../printable"
require_relative "reader"

module Relspec
  module Osdeps
    # The osdeps files of a release and its ancestors, as a package set (or
    # relspec's releases/ folder) holds them: releases.yml for the hierarchy
    # (depends_on), <release>-<arch>.yml for each release. Read as the
    # package set's init.rb reads them (Reader): the release names, and each
    # Debian name the user's system resolves to, checked.
    class ReleaseData
      def initialize(dir)
        @dir = dir
      end

      # Release names from the root of the hierarchy down to +release+.
      def lineage(release)
        path = File.join(@dir, "releases.yml")
        index = checked(Reader.releases(load_yaml(path, required: false) || {}), "release-index", path)
        checked(Reader.lineage(index, release), "release-index", path)
      end

      # autoproj package => Debian name for +os+ (an OperatingSystem), the
      # ancestors' first and later releases overriding earlier ones. A list
      # of names is kept as the published Rock files have it (Reader).
      def resolved(release, arch, os)
        lineage(release).each_with_object({}) do |name, merged|
          path = osdeps_file(name, arch)
          data = load_yaml(path, required: name == release)
          merged.merge!(checked(Reader.resolve(data, os, lists: true), "osdeps-file", path)) unless data.nil?
        end
      end

      def osdeps_file(release, arch)
        flat = File.join(@dir, "#{release}-#{arch}.yml")
        File.file?(flat) ? flat : File.join(@dir, release, "osdeps", "#{release}-#{arch}.yml")
      end

      private

      # YAML with its positions (duplicate keys refused, file:line), nil
      # for a missing file that may be missing.
      def load_yaml(path, required:)
        unless File.file?(path)
          return nil unless required

          raise InvalidInput, [problem("missing-osdeps", "no osdeps file #{Printable.text(path)}", path)]
        end

        document = Yaml::LocatedDocument.load(path)
        raise InvalidInput, document.diagnostics unless document.ok?

        document.data
      end

      def checked(reading, rule, path)
        return reading.value if reading.ok?

        raise InvalidInput, [problem(rule, reading.reason, path)]
      end

      def problem(rule, message, path)
        Diagnostic.error(rule, message, location: Location.file_only(path))
      end
    end
  end
end
