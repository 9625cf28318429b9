# frozen_string_literal: true

require_relative "../apt/dependency"
require_relative "../debian/control_relations"

module Relspec
  module Availability
    # What the release asks of each target distribution: the OS relations
    # of the Build-Depends and Depends that relspec writes into the
    # debian/control of every package it builds there (Debian::ControlRelations,
    # the same lists as Debian::Control, without the relations to Rock packages and
    # without substitution variables), with the packages that need each one.
    class Requirements
      # One comma-separated group of a relationship field: satisfied when any
      # alternative exists. +needed_by+: relspec package names, sorted.
      Relation = Struct.new(:text, :alternatives, :needed_by) do
        def names
          alternatives.map(&:name)
        end
      end

      attr_reader :by_target

      # +planned+: a Plan::Result. Packages built or published here count
      # (inherited ones were checked by the release that built them).
      # +only+: the targets to check (nil: all).
      def self.of(planned, only: nil)
        catalog = planned.catalog
        release_gems = planned.release_gem_names
        targets = planned.plan.targets.select { |target, _| only.nil? || only.include?(target) }
        new(targets.to_h do |target, decisions|
          needs = {}
          decisions.each_value.select { |decision| decision.build? || decision.published? }.each do |decision|
            relations_of(catalog.package(decision.package), target, release_gems).each do |text|
              (needs[text] ||= []) << decision.package
            end
          end
          [target, needs]
        end)
      end

      def self.relations_of(package, target, release_gems)
        os = package.os_dependencies_for(target.codename)
        own_os = Debian::ControlRelations.os_relations(os.apt, Debian::ControlRelations.distribution_gems(os, release_gems))
        type = package.build_type
        relations = Debian::ControlRelations.build_depends(type, [], own_os) +
                    Debian::ControlRelations.depends(type, "all", [], own_os)
        relations.uniq.reject { |text| text.start_with?("${") }
      end
      private_class_method :relations_of

      # +by_target+: Target => {relation text => [package names]}.
      def initialize(by_target)
        @by_target = by_target.to_h do |target, needs|
          relations = needs.sort.filter_map do |text, packages|
            alternatives = applicable(Apt::Dependency.parse(text).first, target.arch)
            Relation.new(text, alternatives, packages.uniq.sort).freeze unless alternatives.empty?
          end
          [target, relations.freeze]
        end.freeze
        freeze
      end

      # Every name to look up on +target+.
      def names(target)
        by_target.fetch(target).flat_map(&:names).uniq.sort
      end

      private

      # Alternatives restricted to other architectures ([amd64], [!arm64])
      # do not apply on this one.
      def applicable(alternatives, arch)
        alternatives.select do |relation|
          list = relation.architectures
          next true if list.empty?

          negated = list.all? { |entry| entry.start_with?("!") }
          negated ? !list.include?("!#{arch}") : list.include?(arch)
        end
      end
    end
  end
end
