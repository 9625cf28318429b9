# frozen_string_literal: true

require_relative "decision"
require_relative "distribution_packages"
require_relative "../debian/naming"
require_relative "../debian/package_version"
require_relative "../debian/gem_version"
require_relative "../catalog/shadowed_gems"

module Relspec
  module Plan
    # Which gems of the release a target takes from its distribution (the
    # Planner's system decisions): a gem the distribution has as
    # ruby-<gem> at the same version, or (a gem packaged without `gems:`)
    # at a version all its requirements accept. What it finds worth saying
    # goes into +notes+ (the plan's notes, an Array it appends to).
    class DistributionGems
      # +distribution+: DistributionPackages; +requirements+: gem name =>
      # [Gem::Requirement] (Catalog::GemResolution#requirements).
      def initialize(distribution:, requirements:, notes:)
        @distribution = distribution
        @requirements = requirements
        @notes = notes
      end

      # The :system Decision of +package+ on +target+, or nil (built or
      # inherited). A blacklisted gem (+cause+) is never taken.
      def decide(package, target, cause)
        return nil unless package.build_type == "gem" && cause&.kind != :blacklisted

        note_missing_dependencies(package, target)
        name = Debian::Naming.distribution_gem(package.name)
        versions = @distribution.versions_of(name, target)
        if versions.empty?
          @notes << "the #{target.codename} archive has no #{name}: gem #{package.name} is packaged here" if @distribution.read?(target)
          return nil
        end

        # the newest that fits: a real ruby-<gem> may be newer than what libruby provides
        if (version = versions.find { |candidate| fits?(package, candidate) })
          return Decision.new(package: package.name, kind: :system, deb_name: name, version: version).freeze
        end

        @notes << "#{target.codename} has #{name} #{versions.join(', ')}, the release packages gem #{package.name} #{package.version}"
        nil
      end

      # name => Catalog::ShadowedGems::Shadowing of the +system+ decisions
      # (name => Decision) on +target+ that cannot be taken: the
      # distribution's package depends on a gem of +packages+ (the selected
      # Catalog::Packages) the release gives itself there, whose copy comes
      # first at run time. One pass is enough: whatever depends on a package
      # given up reaches the same gem through it. Each is noted.
      def shadowed(system, packages, target)
        packaged = packages.select { |package| package.build_type == "gem" && !system.key?(package.name) }
                           .to_h { |package| [package.name, package.version] }
        shadows = Catalog::ShadowedGems.new(depends: @distribution.gem_depends(target), packaged: packaged,
                                            codename: target.codename)
        found = system.keys.sort.filter_map do |name|
          shadows.of(system.fetch(name).deb_name)&.then { |shadowing| [name, shadowing] }
        end.to_h
        found.each { |name, shadowing| @notes << "#{shadowing}: gem #{name} is packaged here" }
        found
      end

      # Says on which targets no gem can come from the distribution, when
      # +catalog+ has gems.
      def note_unavailable(catalog)
        return if catalog.packages.values.none? { |package| package.build_type == "gem" }

        codenames = @distribution.unknown.map(&:codename).uniq.sort
        unless codenames.empty?
          @notes << "gems are packaged here on #{codenames.join(', ')}: no distribution archive to take ruby-* " \
                    "packages from (distributions.<codename>.archive)"
        end
        @distribution.gaps.each { |target, why| @notes << "gems are packaged here on #{target}: #{why}" }
      end

      private

      def fits?(package, version)
        requirements = @requirements[package.name]
        return Debian::GemVersion.debian_upstream(version) == Debian::PackageVersion.of_package(package) unless requirements

        found = Debian::GemVersion.from_debian(version)
        !found.nil? && requirements.all? { |requirement| requirement.satisfied_by?(found) }
      end

      # A gem's runtime dependencies outside the release are the
      # distribution's ruby-<name>; say so when its archive lacks one.
      def note_missing_dependencies(package, target)
        return unless @distribution.read?(target)

        package.os_dependencies_for(target.codename).gems.each do |dependency|
          name = Debian::Naming.distribution_gem(dependency)
          next if @distribution.version_of(name, target)

          @notes << "gem #{package.name} needs #{dependency}, which the #{target.codename} archive lacks as #{name} " \
                    "(add it to gems:)"
        end
      end
    end
  end
end
