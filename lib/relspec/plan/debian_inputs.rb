# frozen_string_literal: true

require_relative "../debian/control_relations"
require_relative "../debian/build_input"
require_relative "../release_specs/values/prefixes"
require_relative "../catalog/prefix_markers"
require_relative "../catalog/ruby_extension"
require_relative "../catalog/cmake_defines"

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
        # install folders by where a package comes from: every dependent
        # asks, so computed once
        @install_dirs = {}
        # what a package's closure gives its build (tools, environment
        # variables), by kind, target and name
        @closure = {}
      end

      # +decisions+: the target's decisions, those of dependencies settled.
      def for(target, decision, upstream, decisions)
        package = @release_catalog.catalog.package(decision.package)
        os = package.os_dependencies_for(target.codename)
        distribution = @effective.distributions.fetch(target.codename)
        Debian::BuildInput.new(
          package: package, deb_name: decision.deb_name, upstream: upstream, codename: target.codename,
          release: @effective.release, maintainer: @effective.maintainer, install_dir: install_dir_of(decision),
          debhelper_compat: distribution.debhelper_compat, ruby_dirs: distribution.ruby_install_dirs(target.arch),
          dependencies: dependencies_of(package, decisions), apt: os.apt,
          gems: Debian::ControlRelations.distribution_gems(os, @release_catalog.gems.keys),
          gem: @release_catalog.gems[package.name],
          closure_tools: closure_tools(package, target, decisions),
          closure_environment: closure_environment(package, target, decisions),
          defines: defines_of(package, decisions, distribution.ruby_executable),
          extension_task: Catalog::RubyExtension.checked(package)
        )
      end

      # +package+'s CMake defines (pkg.define) for the target: a reference
      # to another package's prefix (Catalog::PrefixMarkers) becomes the
      # prefix the release gives that package there; a define naming a
      # package without a decision on the target is left out, as if the
      # package set had not seen the package. A define naming the
      # workspace's Ruby (Catalog::CmakeDefines::RUBY) gets +ruby+, the
      # target's.
      def defines_of(package, decisions, ruby)
        prefixes = prefixes_of(package, decisions)
        package.defines.filter_map do |name, value|
          names = value.scan(Catalog::PrefixMarkers::REFERENCE).flatten
          next unless names.all? { |reference| prefixes.key?(reference) }

          [name, value.gsub(Catalog::PrefixMarkers::REFERENCE) { prefixes.fetch(Regexp.last_match(1)) }
                      .gsub(Catalog::CmakeDefines::RUBY) { ruby }]
        end.to_h
      end

      # The prefixes on the target of the packages +package+'s defines
      # name (Catalog::PrefixMarkers): where the release installs them; a
      # package of the distribution lives in /usr. Those without a decision
      # on the target are left out.
      def prefixes_of(package, decisions)
        names = package.defines.values.flat_map { |value| value.scan(Catalog::PrefixMarkers::REFERENCE).flatten }
        names.uniq.select { |name| decisions.key?(name) }.sort.to_h do |name|
          [name, install_dir_of(decisions[name]) || "/usr"]
        end
      end

      # The folder a decided package installs into; nil for the
      # distribution's own packages, which live in the system.
      def install_dir_of(decision)
        return nil if decision.system?

        key = [decision.inherit? && decision.ancestor, decision.deb_name]
        @install_dirs.fetch(key) { @install_dirs[key] = compute_install_dir(decision) }
      end

      # The dependencies of +package+ that debian/ names: those with a
      # decision on the target, in the package's order.
      def dependency_names(package, decisions)
        package.build_dependencies.select { |name| decisions.key?(name) }
      end

      # The build-only tools (Debian::ControlRelations.build_only) of every
      # package in +package+'s dependency closure on the target, sorted:
      # what autoproj would have installed before building it, that the
      # dependencies' Depends do not bring. The distribution's own packages
      # (system decisions) bring what they need themselves.
      def closure_tools(package, target, decisions)
        closure(:tools, package, target, decisions) do |dependency|
          apt = dependency.os_dependencies_for(target.codename).apt
          Debian::ControlRelations.build_only(dependency.build_type, apt)
        end
      end

      # The variables the package sets' environment settings of +package+'s
      # closure name (Catalog::Package#environment), sorted: the
      # dependencies' env.sh export them, and the build takes them as
      # autoproj's build would (rock.core's OROGEN_PLUGIN_PATH, where oroGen
      # finds tools/orogen_metadata's plugin that --extensions=metadata_support
      # asks for).
      def closure_environment(package, target, decisions)
        closure(:environment, package, target, decisions) do |dependency|
          dependency.environment.map { |op| op.fetch("name") }.select { |name| Debian::BuildInput.variable?(name) }
        end
      end

      # What +own+ gives each release package of +package+'s dependency
      # closure on the target, once each, sorted; computed once per package.
      def closure(kind, package, target, decisions, visiting = {}, &own)
        dependency_names(package, decisions).reject { |name| decisions[name].system? }.flat_map do |name|
          key = [kind, target.to_s, name]
          @closure.fetch(key) do
            next [] if visiting[name] || !@release_catalog.catalog.package?(name)

            visiting[name] = true
            dependency = @release_catalog.catalog.package(name)
            @closure[key] = (own.call(dependency) + closure(kind, dependency, target, decisions, visiting, &own))
                            .uniq.sort.freeze
          end
        end.uniq.sort
      end

      private

      def compute_install_dir(decision)
        if decision.inherit?
          ancestor = @ancestors.fetch(decision.ancestor)
          ancestor.prefixes.install_dir(ancestor.name, decision.deb_name)
        else
          @effective.prefixes.install_dir(@effective.release, decision.deb_name)
        end
      end

      def dependencies_of(package, decisions)
        dependency_names(package, decisions).map do |name|
          decision = decisions[name]
          Debian::BuildInput::Dependency.new(deb_name: decision.deb_name, version: decision.version.to_s,
                                             install_dir: install_dir_of(decision))
        end
      end
    end
  end
end
