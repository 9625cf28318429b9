# frozen_string_literal: true

require_relative "snapshot"
require_relative "../error"
require_relative "../yaml/located_document"

module Relspec
  module Diff
    # The one place where the diff reads a lock: plain lock data (what
    # Plan::Lock reads or generates) becomes the diff's own Snapshot. When
    # the lock reader changes, only this file follows it.
    module LockView
      module_function

      # A lock file's text (+source+ names it in messages) as a Snapshot.
      def parse(text, source:)
        document = Yaml::LocatedDocument.parse(text, file: source)
        raise InvalidInput, document.diagnostics unless document.ok?

        snapshot(document.data, source: source)
      end

      # +data+: the lock's content as a Hash; +source+: where it was read.
      def snapshot(data, source:)
        raise Error, "#{source} is not a relspec lock" unless data.is_a?(Hash) && data.key?("relspec_lock")

        Snapshot.new(release: data["release"].to_s, source: source, spec_digest: data["spec_digest"],
                      ancestors: hash(data["ancestors"]).transform_values { |codenames| hash(codenames).dup.freeze }.freeze,
                      packages: hash(data["packages"]).transform_values { |entry| source_of(entry) }.freeze,
                      targets: hash(data["targets"]).transform_values { |entries| decisions(entries) }.freeze,
                      spec: nil).freeze
      end

      def decisions(entries)
        hash(entries).transform_values do |entry|
          entry = hash(entry)
          Decision.new(kind: entry["decision"].to_s, deb: entry["deb"], version: entry["version"]&.to_s,
                       from: entry["from"], causes: Array(entry["causes"]).map(&:to_s).freeze).freeze
        end.freeze
      end

      def source_of(entry)
        entry = hash(entry)
        PackageSource.new(url: entry["url"], commit: entry["commit"], commit_time: entry["commit_time"],
                          version: entry["version"]&.to_s).freeze
      end

      def hash(value)
        value.is_a?(Hash) ? value : {}
      end
    end
  end
end
