# frozen_string_literal: true

require_relative "../debian/control_relations"

module Relspec
  module Plan
    # What the debian/ of one build is made from (the input of
    # Debian::DebianDir): the catalog package, its name and upstream version,
    # the release's settings, and its dependencies as the plan decided them
    # on this target (name, version, install folder).
    class DebianInputs
      # +effective+: EffectiveSpec; +ancestors+: [Ancestor];
      # +release_catalog+: Catalog::ReleaseCatalog.
      def initialize(effective:, ancestors:, release_catalog:)
        @effective = effective
        @ancestors = ancestors.to_h { |ancestor| [ancestor.name, ancestor] }
        @release_catalog = release_catalog
      end

      # +decisions+: the target's decisions, those of dependencies settled.
      def for(target, decision, upstream, decisions)
        package = @release_catalog.catalog.package(decision.package)
        os = package.os_dependencies_for(target.codename)
        {
          package: package, deb_name: decision.deb_name, upstream: upstream, codename: target.codename,
          release: @effective.release, maintainer: @effective["maintainer"], install_dir: install_dir_of(decision),
          debhelper_compat: @effective.distributions.fetch(target.codename).debhelper_compat,
          dependencies: dependencies_of(package, decisions), closure: closure_dirs(package, decisions), apt: os.apt,
          gems: Debian::ControlRelations.distribution_gems(os, @release_catalog.gems.keys),
          gem: @release_catalog.gems[package.name]
        }
      end

      # The folder a decided package installs into; nil for the
      # distribution's own packages, which live in the system.
      def install_dir_of(decision)
        return nil if decision.system?

        if decision.inherit?
          ancestor = @ancestors.fetch(decision.ancestor)
          prefix_dir(ancestor.install_prefix, ancestor.name, ancestor.separate_prefixes, decision.deb_name)
        else
          prefix_dir(@effective["install_prefix"], @effective.release, @effective["separate_prefixes"] != false,
                     decision.deb_name)
        end
      end

      private

      def dependencies_of(package, decisions)
        package.build_dependencies.filter_map do |name|
          decision = decisions[name]
          decision && { deb_name: decision.deb_name, version: decision.version.to_s, install_dir: install_dir_of(decision) }
        end
      end

      # The prefixes of the whole dependency closure, own and inherited,
      # breadth first from the package (its direct dependencies by name, then
      # theirs), each once: a dependency's CMake configuration or pkg-config
      # file names its own dependencies, which the build must find too.
      def closure_dirs(package, decisions)
        catalog = @release_catalog.catalog
        seen = {}
        queue = package.build_dependencies.dup
        dirs = []
        until queue.empty?
          name = queue.shift
          next if seen[name]

          seen[name] = true
          decision = decisions[name]
          next unless decision && (dir = install_dir_of(decision))

          dirs << dir
          queue.concat(catalog.package(name).build_dependencies) if catalog.package?(name)
        end
        dirs.uniq
      end

      def prefix_dir(install_prefix, release, separate, deb_name)
        base = File.join(install_prefix, release)
        separate ? File.join(base, deb_name) : base
      end
    end
  end
end
