# frozen_string_literal: true

require_relative "repository_entry"
require_relative "../../frozen"

module Relspec
  module ReleaseSpec
    # A distribution's `archive:` (Schema::ARCHIVE), as written: a repository
    # (path, url, keyring, trusted) and its components, or host: true for
    # this machine's apt lists. The one place its fields are defined; the
    # spec's rules have checked their types before one is made.
    Archive = Struct.new(:path, :url, :keyring, :trusted, :components, :host, keyword_init: true) do
      # A frozen Archive of the mapping +entry+ (an Archive is kept), or nil
      # when there is none (or it is no mapping: the spec's rules say so).
      def self.from(entry)
        return entry if entry.is_a?(self)
        return nil unless entry.is_a?(Hash)

        new(**members.to_h { |member| [member, Frozen.deep(entry[member.to_s])] }).freeze
      end

      # Read this machine's apt lists instead of a repository.
      def host?
        host == true
      end

      # The components read ("main" when none are written).
      def read_components
        components || ["main"].freeze
      end

      # The repository to read, its relative paths resolved against +base+
      # (the folder of the spec that wrote it).
      def repository_entry(base)
        RepositoryEntry.from({ "path" => path, "url" => url, "keyring" => keyring, "trusted" => trusted }.compact, base: base)
      end

      # The mapping as written.
      def to_h
        self.class.members.to_h { |member| [member.to_s, self[member]] }.compact
      end
    end
  end
end
