# frozen_string_literal: true

require_relative "../apt/opening"
require_relative "values/prefixes"

module Relspec
  module ReleaseSpec
    # A release's repositories: the release itself first, then every
    # ancestor in search order, each with its prefixes, the targets it was
    # built for and where its repository is declared. Read once from a
    # Resolution and handed to plan, publish, mirror, check, builder and abi.
    class Lineage
      include Enumerable

      # +repository+: its RepositoryEntry (nil: none declared); +targets+:
      # codename → arches (nil: unknown, every target is tried, as for an
      # external release without `targets:`); +location+: the spec line
      # that declares the repository.
      Member = Struct.new(:name, :repository, :prefixes, :targets, :location, keyword_init: true) do
        def initialize(**)
          super
          freeze
        end

        def target?(target)
          targets.nil? || Array(targets[target.codename]).include?(target.arch)
        end

        def package_prefix
          prefixes.package_prefix
        end

        # The member's repository as an Apt::Repository at +location+ (where
        # a reader finds it by default); nil when it declares none.
        def open(fetcher_options: {}, cache: Apt::Cache.new(nil), location: repository&.location)
          repository && Apt::Opening.repository(repository, location, fetcher_options: fetcher_options, cache: cache)
        end
      end

      # A member with its repository opened for reading; what planning and
      # the stages after it look ancestors' packages up in.
      Opened = Struct.new(:member, :repository) do
        def initialize(*)
          super
          freeze
        end

        %i[name prefixes targets location package_prefix target?].each do |name|
          define_method(name) { |*args| member.public_send(name, *args) }
        end
      end

      attr_reader :own, :ancestors

      def self.of(resolution)
        effective = resolution.effective
        own = Member.new(name: effective.release, repository: effective.repository, prefixes: effective.prefixes,
                         targets: effective.targets, location: resolution.spec_file.key_location(["repository"]))
        new(own, resolution.hierarchy.ancestors.map { |node| ancestor(resolution.hierarchy.library, node) })
      end

      def self.ancestor(library, node)
        return external(node.source) if node.external?

        resolution = Resolution.new(library, node.source)
        effective = resolution.effective
        repository = effective.repository
        Member.new(name: effective.release, repository: repository, prefixes: effective.prefixes, targets: effective.targets,
                   location: resolution.spec_file.key_location(repository ? ["repository"] : ["release"]))
      end

      def self.external(release)
        Member.new(name: release.name, repository: release.repository, prefixes: release.prefixes,
                   targets: release.value("targets"), location: release.location)
      end
      private_class_method :ancestor, :external

      def initialize(own, ancestors)
        @own = own
        @ancestors = ancestors.freeze
        freeze
      end

      def each(&)
        [own, *ancestors].each(&)
      end

      # The ancestors, each opened as an apt repository (nil when it
      # declares none), in search order.
      def opened_ancestors(fetcher_options: {}, cache: Apt::Cache.new(nil))
        ancestors.map { |member| Opened.new(member, member.open(fetcher_options: fetcher_options, cache: cache)) }
      end
    end
  end
end
