# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # A `repository:` (or `external:`, or distribution archive) entry with its
    # relative paths resolved against the folder of the spec that wrote it.
    # +path+ and +keyring+ are absolute (or nil), +url+ as written;
    # +debug_symbols+ (own repository only): publish the -dbgsym packages.
    RepositoryEntry = Struct.new(:path, :url, :keyring, :trusted, :sign_with, :debug_symbols, keyword_init: true) do
      # +entry+: the mapping as written; +base+: the declaring spec's folder.
      # nil when +entry+ is not a mapping.
      def self.from(entry, base:)
        return nil unless entry.is_a?(Hash)

        new(path: entry["path"] && File.expand_path(entry["path"], base), url: entry["url"],
            keyring: entry["keyring"] && File.expand_path(entry["keyring"], base),
            trusted: entry["trusted"] == true, sign_with: entry["sign_with"],
            debug_symbols: entry["debug_symbols"] == true)
      end

      def initialize(**)
        super
        freeze
      end

      # Where a reader finds the repository: the local path when it exists
      # (or when there is no URL to ask instead), else the URL.
      def location
        path && (File.directory?(path) || !url) ? path : url
      end

      # Where the release itself publishes: its path, which may not exist yet
      # (an empty repository, never a reason to ask the URL).
      def own_location
        path || url
      end
    end
  end
end
