# frozen_string_literal: true

module Relspec
  class Catalog
    # Where a package's source comes from. +commit+ is what the checkout holds
    # (or what a pin fixes); branch and tag are what autoproj would follow;
    # +sha256+ is the checksum of an archive import's tarball (ArchiveImport).
    Vcs = Struct.new(:type, :url, :branch, :tag, :commit, :sha256, keyword_init: true) do
      def self.from_h(hash)
        new(**hash.transform_keys(&:to_sym)).freeze
      end

      def to_h
        super.transform_keys(&:to_s).compact
      end

      # The source with a spec pin ({"commit"|"tag"|"branch" => value})
      # applied: a pin replaces what autoproj would follow.
      def pinned(pin)
        ref, value = pin.first
        case ref
        when "commit" then self.class.new(**to_h.transform_keys(&:to_sym), commit: value).freeze
        when "tag" then self.class.new(type: type, url: url, tag: value).freeze
        when "branch" then self.class.new(type: type, url: url, branch: value).freeze
        end
      end
    end
  end
end
