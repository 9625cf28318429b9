# frozen_string_literal: true

require_relative "package"
require_relative "gem_archive"
require_relative "../debian/naming"
require_relative "../cache_dir"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  class Catalog
    # The third-party gems of a spec's `gems:` become packages of the
    # release (build type "gem", named by the gem as autoproj's osdeps name
    # gems): made from the published .gem, depending on the other gems of
    # the release they need, and needed by every workspace package whose
    # OS dependencies name them. Their other runtime dependencies stay OS
    # dependencies (the distribution's ruby-* packages).
    module ReleaseGems
      module_function

      # +gems+: name => version; +fetch+: (name, version) → GemArchive;
      # +locate+: name → Location of its `gems:` entry; +names+: codename =>
      # selected names; +provided+: the names of +gems+ every target's
      # distribution has at that version, added without their .gem (nothing
      # is built from it). Returns [catalog, names, archives] with the gems
      # added. Raises InvalidInput.
      def add(catalog, gems, names, fetch:, locate:, provided: [])
        return [catalog, names, {}] if gems.empty?

        archives = fetch_all(catalog, gems.except(*provided), fetch, locate)
        check_requirements(archives, locate)
        check_constraints(catalog, names, archives, locate)
        packages = archives.to_h { |name, archive| [name, package_of(archive, archives, catalog.codenames)] }
        provided.each { |name| packages[name] = provided_package(name, gems.fetch(name), catalog.codenames) }
        users = catalog.packages.transform_values { |package| with_gem_dependencies(package, packages.keys, catalog.codenames) }
        extended = catalog.with_packages(users.merge(packages))
        [extended, names.transform_values { |list| (list + packages.keys).uniq.sort.freeze }, archives]
      end

      # A gem the distribution provides on every target: the plan takes
      # ruby-<gem>, so what the .gem holds (files, dependencies) is never read.
      def provided_package(name, version, codenames)
        Package.new(name: name, package_set: nil, build_type: "gem", vcs: Vcs.new(type: "gem", url: nil, commit: nil).freeze,
                    commit_time: nil, source_dir: nil, version: version, dependencies: [],
                    os_dependencies: codenames.to_h { |codename| [codename, OsDependencies::EMPTY] })
      end

      def fetch_all(catalog, gems, fetch, locate)
        problems = []
        archives = gems.sort.to_h do |name, version|
          if catalog.package?(name)
            problems << Diagnostic.error("gem-name", "gem #{name} has the name of a package of the workspace",
                                         location: locate.call(name), hint: "package it from the workspace, or rename one")
            next [name, nil]
          end
          [name, fetch.call(name, version)]
        rescue GemArchive::Problem => e
          problems << Diagnostic.error("gem-source", e.message, location: locate.call(name),
                                                                hint: "check gem_source and the version")
          [name, nil]
        end
        raise InvalidInput, problems unless problems.empty?

        archives
      end

      # A gem of the release that another one needs must be at a version
      # that one accepts: apt would refuse to install them together.
      def check_requirements(archives, locate)
        problems = archives.values.flat_map do |archive|
          archive.runtime_dependencies.filter_map do |dependency, requirement|
            other = archives[dependency]
            next unless other && !requirement.satisfied_by?(Gem::Version.new(other.version))

            Diagnostic.error("gem-requirement", "gem #{archive.name} #{archive.version} needs #{dependency} " \
                                                "#{requirement}, the release packages #{dependency} #{other.version}",
                             location: locate.call(dependency), hint: "pick versions that fit together")
          end
        end
        raise InvalidInput, problems unless problems.empty?
      end

      # An osdeps gem entry may carry a version constraint ("rice<4.0.0":
      # Rock's bindings need the Rice 3 API); a version of `gems:` outside it
      # is what autoproj would never install for that package. Only the
      # selected packages count: the others are not in the release.
      def check_constraints(catalog, names, archives, locate)
        selected = names.flat_map { |codename, list| list.select { |name| catalog.package?(name) }.map { |name| [name, codename] } }
        problems = selected.group_by(&:first).sort.flat_map do |name, pairs|
          package = catalog.package(name)
          entries = pairs.flat_map { |_, codename| package.os_dependencies_for(codename).gems }.uniq
          entries.filter_map do |entry|
            gem = Debian::Naming.gem_name(entry)
            requirement = requirement_of(entry, gem)
            archive = archives[gem]
            next unless archive && requirement && !requirement.satisfied_by?(Gem::Version.new(archive.version))

            Diagnostic.error("gem-constraint", "#{name}'s osdeps ask for gem #{gem} #{requirement}, the release " \
                                               "packages #{gem} #{archive.version}",
                             location: locate.call(gem), hint: "pick a version of #{gem} that fits #{requirement}")
          end
        end
        raise InvalidInput, problems unless problems.empty?
      end

      # The Gem::Requirement of an osdeps gem entry, nil without one (or
      # with one RubyGems cannot read, which autoproj would not accept either).
      def requirement_of(entry, gem)
        text = entry.delete_prefix(gem).strip
        return nil if text.empty?

        Gem::Requirement.new(*text.split(",").map(&:strip))
      rescue Gem::Requirement::BadRequirementError
        nil
      end

      def package_of(archive, archives, codenames)
        spec = archive.spec
        needed = archive.runtime_dependencies.map(&:first)
        # written as osdeps gem entries ("baz>= 1.0"), so that the distribution's
        # ruby-baz keeps the version the gem asks for
        outside = archive.runtime_dependencies.reject { |name, _| archives.key?(name) }
                         .map { |name, requirement| "#{name}#{requirement unless requirement.none?}" }
        os = OsDependencies.build(apt: archive.native? ? %w[ruby-dev] : [], gems: outside)
        Package.new(name: archive.name, package_set: nil, build_type: "gem",
                    vcs: Vcs.new(type: "gem", url: archive.origin, commit: archive.sha256).freeze,
                    commit_time: archive.time, source_dir: nil, version: archive.version,
                    summary: spec.summary, description: spec.description, license: spec.licenses.join(" or ").then { |l| l.empty? ? nil : l },
                    maintainer: spec.authors.empty? ? nil : spec.authors.join(", "),
                    dependencies: needed & archives.keys, os_dependencies: codenames.to_h { |codename| [codename, os] })
      end

      def with_gem_dependencies(package, gem_names, codenames)
        used = codenames.flat_map { |codename| package.os_dependencies_for(codename).gems }
                        .map { |entry| Debian::Naming.gem_name(entry) } & gem_names
        used.empty? ? package : package.with(dependencies: package.dependencies + used)
      end

      # Fetches from the effective spec's gem_source, downloads cached in
      # the XDG cache; each .gem is read once per run.
      def fetcher(effective, spec_dir, timeout: 10, cache_dir: CacheDir.for("gems"))
        read = {}
        lambda do |name, version|
          read[[name, version]] ||= GemArchive.fetch(name, version, source: effective.gem_source, base_dir: spec_dir,
                                                                    cache_dir: cache_dir, timeout: timeout)
        end
      end
    end
  end
end
