# frozen_string_literal: true

require "digest"
require_relative "../apt/repository"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # What each ancestor's repository holds for each target: one Release read
    # per ancestor and codename, one Packages index per ancestor and target —
    # never one request per package.
    #
    # An ancestor is identified in the lock by a digest of what it provides
    # (the sorted name, version and architecture of every index entry read
    # for a codename), not by its Release file: a Release file carries a date,
    # so re-exporting or rebuilding a repository with the same content would
    # otherwise change every child's lock.
    class Inventory
      attr_reader :release_digests

      # Raises InvalidInput naming the ancestor and the URL of every
      # repository that cannot be read.
      def self.read(ancestors, targets)
        indices = {}
        problems = []
        ancestors.each do |ancestor|
          targets.each do |target|
            next unless ancestor.target?(target)

            if ancestor.repository.nil?
              problems << no_repository(ancestor)
              break
            end
            begin
              repository = ancestor.repository
              indices[[ancestor.name, target]] = repository.packages(target.codename, target.arch)
            rescue Apt::Repository::Error => e
              problems << Diagnostic.error("ancestor-repository", "ancestor #{ancestor.name}: #{e.message}",
                                           location: ancestor.location,
                                           hint: "check the repository of #{ancestor.name}, or the network")
              break
            end
          end
        end
        raise InvalidInput, problems unless problems.empty?

        new(indices, content_digests(indices))
      end

      # [ancestor, codename] => SHA256 over "arch name version" lines, sorted.
      def self.content_digests(indices)
        indices.group_by { |(ancestor, target), _| [ancestor, target.codename] }.to_h do |key, entries|
          lines = entries.flat_map do |(_, target), index|
            index.entries.each_value.map { |entry| "#{target.arch} #{entry.name} #{entry.version}\n" }
          end
          [key, Digest::SHA256.hexdigest(lines.sort.join)]
        end
      end

      def self.no_repository(ancestor)
        Diagnostic.error("ancestor-repository", "ancestor #{ancestor.name} declares no repository to inherit from",
                         location: ancestor.location, hint: "add `repository:` (path and/or url) to #{ancestor.name}")
      end

      def initialize(indices, release_digests)
        @indices = indices.freeze
        @release_digests = release_digests.freeze
        freeze
      end

      # The ancestor's index for +target+, or nil if it does not have the target.
      def index(ancestor_name, target)
        @indices[[ancestor_name, target]]
      end

      def target?(ancestor_name, target)
        @indices.key?([ancestor_name, target])
      end
    end

    # What the release's own repository already holds. A repository that
    # does not exist yet (or lacks a codename) simply holds nothing.
    class OwnRepository
      def self.read(repository, targets)
        return new({}) unless repository

        indices = {}
        targets.each do |target|
          indices[target] = repository.packages(target.codename, target.arch)
        rescue Apt::Repository::Missing
          next
        end
        new(indices)
      end

      def initialize(indices)
        @indices = indices.freeze
        freeze
      end

      def version_of(deb_name, target)
        @indices[target]&.[](deb_name)&.version
      end
    end
  end
end
