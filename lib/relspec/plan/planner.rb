# frozen_string_literal: true

require_relative "cause"
require_relative "decision"
require_relative "release_plan"
require_relative "distribution_packages"
require_relative "distribution_gems"
require_relative "../catalog/gem_resolution"
require_relative "../apt/version"
require_relative "../debian/naming"
require_relative "../debian/package_version"
require_relative "../release_specs/package_pattern"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # Decides, for every target and every package of the release, whether it
    # is inherited from an ancestor, already published here, or built here,
    # and why (docs/plan.md):
    #
    # - a package is built when it is blacklisted, pinned to a commit no
    #   ancestor has, missing in all ancestors, or when no ancestor has the
    #   target at all;
    # - everything that depends on a rebuilt package is rebuilt too, because
    #   an inherited binary must never run against a different build of its
    #   dependency;
    # - the nearest ancestor (in search order) that has the package's Debian
    #   name provides it.
    class Planner
      # +release_catalog+: Catalog::ReleaseCatalog; +effective+: the
      # release's EffectiveSpec; +spec_file+: its SpecFile (for locations);
      # +ancestors+: ReleaseSpec::Lineage::Opened in search order; +inventory+: Inventory;
      # +distribution+: DistributionPackages (the targets' own ruby-* packages,
      # DistributionGems decides which gems come from them);
      # +uncommitted+: name => Catalog::UncommittedChanges::Change (noted).
      # Builds come out unversioned: Settlement gives them their versions.
      def initialize(release_catalog:, effective:, spec_file:, ancestors:, inventory:,
                     distribution: DistributionPackages.new({}, []), uncommitted: {})
        @catalog = release_catalog.catalog
        @selections = release_catalog.selections
        @effective = effective
        @spec_file = spec_file
        @ancestors = ancestors
        @inventory = inventory
        @warnings = []
        @notes = release_catalog.gem_resolution.notes.dup
        @gems = DistributionGems.new(distribution: distribution, requirements: release_catalog.gem_resolution.requirements,
                                     notes: @notes)
        @uncommitted = uncommitted
      end

      def plan
        blacklist = blacklist_entries
        targets = Target.all(@effective)
        unavailable = targets.to_h { |target| [target, unavailable_on(target)] }
        decisions = targets.to_h { |target| [target, plan_target(target, blacklist, unavailable[target])] }
        @gems.note_unavailable(@catalog)
        # what a checkout holds beyond its commit is not in the release
        @uncommitted.sort.each { |name, change| @notes << change.note(name) }
        ReleasePlan.new(release: @effective.release, targets: decisions, packages: package_records(decisions, unavailable),
                        release_digests: @inventory.release_digests, warnings: merged_warnings, notes: @notes.uniq.sort,
                        unavailable: unavailable)
      end

      private

      def plan_target(target, blacklist, unavailable)
        names = @selections.fetch(target.codename).names
        names.each { |name| note_optional_missing(@catalog.package(name), target, unavailable) }
        providers = names.to_h { |name| [name, providers_of(@catalog.package(name), target)] }
        causes = names.to_h { |name| [name, direct_cause(@catalog.package(name), target, providers[name], blacklist)] }.compact
        system = names.to_h { |name| [name, @gems.decide(@catalog.package(name), target, causes[name])] }.compact
        @gems.shadowed(system, names.map { |name| @catalog.package(name) }, target).each do |name, shadowing|
          system.delete(name)
          # built here, and why (one an ancestor has at its version is inherited)
          causes[name] = Cause.shadowed_gem(shadowing) if causes.key?(name)
        end
        causes.reject! { |name, _| system.key?(name) }
        rebuild_dependents(names - system.keys, causes)
        names.to_h { |name| [name, system[name] || decide(@catalog.package(name), target, providers[name], causes[name])] }
      end

      # name => Cause for the selected packages the target cannot have.
      def unavailable_on(target)
        reasons = @selections.fetch(target.codename).unavailable
        causes = {}
        cause_of = lambda do |name|
          causes[name] ||= begin
            reason = reasons.fetch(name)
            if reason.dependency
              Cause.unavailable_dependency(reason.dependency, cause_of.call(reason.dependency))
            elsif reason.left_out
              Cause.left_out(reason.left_out.pattern.source, reason.left_out.reason)
            elsif reason.excluded
              Cause.excluded(reason.excluded)
            elsif reason.other_os && !reason.osdeps
              Cause.other_os_osdeps(reason.other_os, target.codename)
            else
              Cause.nonexistent_osdeps(reason.osdeps, target.codename)
            end
          end
        end
        reasons.keys.sort.to_h { |name| [name, cause_of.call(name)] }
      end

      # [[ancestor, index entry], …] in search order.
      def providers_of(package, target)
        @ancestors.filter_map do |ancestor|
          index = @inventory.index(ancestor.name, target)
          entry = index && index[deb_name(package, ancestor.package_prefix, ancestor.name)]
          entry && [ancestor, entry]
        end
      end

      def direct_cause(package, target, providers, blacklist)
        entry = blacklist.find { |candidate| candidate.match?(package.name) }
        return Cause.blacklisted(entry.pattern.source, entry.reason) if entry

        pinned = pin_cause(package, providers)
        return pinned if pinned

        gem = gem_cause(package, providers)
        return gem if gem
        return Cause.missing if @ancestors.empty?
        return Cause.no_ancestor_target(target) if @ancestors.none? { |a| @inventory.target?(a.name, target) }
        return Cause.missing if providers.empty?

        nil
      end

      def pin_cause(package, providers)
        pin = @effective.pins[package.name]
        return nil unless pin

        ref = pin.ref
        value = pin.value
        label = ref == "commit" ? nil : "#{ref} #{value}"
        ours = upstream(package)
        nearest = providers.first
        return nil if nearest && ours && Debian::PackageVersion.upstream_of(nearest[1].version) == ours

        Cause.pinned(package.vcs.commit || value, label)
      end

      # A gem's version is fixed by the spec: an ancestor with another
      # version cannot provide it.
      def gem_cause(package, providers)
        return nil unless package.build_type == "gem" && (nearest = providers.first)

        theirs = Debian::PackageVersion.upstream_of(nearest[1].version)
        theirs == upstream(package) ? nil : Cause.gem_version(upstream(package), nearest[0].name, theirs || nearest[1].version)
      end

      # Breadth first from the rebuilt packages along reverse dependencies,
      # so each package gets the shortest chain (ties broken by name).
      def rebuild_dependents(names, causes)
        selected = names.to_h { |name| [name, true] }
        dependents = Hash.new { |hash, key| hash[key] = [] }
        names.each do |name|
          package = @catalog.package(name)
          package.build_dependencies.each do |dependency|
            dependents[dependency] << name if selected[dependency]
          end
        end
        frontier = causes.keys.sort
        until frontier.empty?
          reached = []
          frontier.each do |dependency|
            dependents[dependency].sort.each do |dependent|
              next if causes.key?(dependent)

              causes[dependent] = Cause.depends_on(dependency, causes[dependency])
              reached << dependent
            end
          end
          frontier = reached.sort
        end
      end

      def decide(package, target, providers, cause)
        if cause
          built(package, target, cause)
        else
          ancestor, entry = providers.first
          note_shadowing(package, target, providers)
          note_drift(package, ancestor, entry)
          Decision.new(package: package.name, kind: :inherit, deb_name: entry.name, version: entry.version,
                       ancestor: ancestor.name).freeze
        end
      end

      def built(package, _target, cause)
        deb = deb_name(package, @effective.prefixes.package_prefix, @effective.release)
        unless upstream(package)
          raise InvalidInput, [Diagnostic.error("unknown-commit-time",
                                                "cannot version #{package.name}: the time of its commit is unknown",
                                                location: @spec_file.location(["workspace"]),
                                                hint: "plan from the workspace rather than a snapshot for pins by tag or branch")]
        end
        note_archive(package)
        Decision.new(package: package.name, kind: :build, deb_name: deb, cause: cause).freeze
      end

      # Where an archive import's source comes from (notes are said once).
      def note_archive(package)
        return unless (sha256 = package.vcs.sha256)

        @notes << "#{package.name} is imported from the archive #{package.vcs.url} (sha256 #{sha256}, modified #{package.commit_time})"
      end

      def upstream(package)
        Debian::PackageVersion.of_package(package)
      end

      def deb_name(package, prefix, release)
        Debian::Naming.deb_name(prefix: prefix, release: release, package_name: package.name,
                                build_type: package.build_type)
      end

      # autoproj leaves out an optional dependency the distribution cannot
      # have (an osdep without package there, a package unavailable there:
      # +unavailable+, name => Cause); the package is built without it, which plan says.
      def note_optional_missing(package, target, unavailable)
        why = package.os_dependencies_for(target.codename).optional_missing.to_h { |name| [name, "the osdeps define no package for it there"] }
        (package.optional_dependencies & unavailable.keys).each { |name| why[name] = "it is unavailable there (#{unavailable[name]})" }
        why.sort.each { |name, reason| @notes << "#{package.name} is built without its optional dependency #{name} on #{target.codename}: #{reason}" }
      end

      def note_shadowing(package, target, providers)
        return if providers.size < 2

        @warnings << [package.name, providers.map { |ancestor, _| ancestor.name }, target.to_s]
      end

      def note_drift(package, ancestor, entry)
        theirs = Debian::PackageVersion.upstream_of(entry.version)
        ours = upstream(package)
        return unless theirs && ours && Apt::Version.parse(ours) > Apt::Version.parse(theirs)

        @notes << "drift: #{package.name} is at #{ours} in the workspace, #{ancestor.name} has #{theirs}"
      end

      # One warning per shadowed package, listing the targets.
      def merged_warnings
        @warnings.group_by { |name, providers, _| [name, providers] }.sort.map do |(name, providers), entries|
          targets = entries.map(&:last).uniq.sort.join(", ")
          Diagnostic.warning("shadowed-package",
                             "#{name} is provided by #{providers.join(' and ')} (#{targets}); " \
                             "#{providers.first} is nearer and wins",
                             location: @spec_file.location(["parent"]),
                             hint: "blacklist it to rebuild it here, or remove it from the farther release")
        end
      end

      # The spec's blacklist (ReleaseSpec::BlacklistEntry, in spec order);
      # an entry that matches no package of the workspace is an error.
      def blacklist_entries
        entries = @effective.blacklist
        unmatched = entries.reject { |entry| @catalog.packages.keys.any? { |name| entry.match?(name) } }
        unless unmatched.empty?
          raise(InvalidInput, unmatched.map do |entry|
            Diagnostic.error("unmatched-blacklist", "blacklist entry #{entry.pattern.source.inspect} matches no package " \
                                                    "of the workspace",
                             location: @spec_file.location(["blacklist", entry.index]),
                             hint: "check the name, or remove the entry")
          end)
        end
        entries
      end

      def package_records(decisions, unavailable)
        names = (decisions.values + unavailable.values).flat_map(&:keys).uniq.sort
        names.to_h do |name|
          package = @catalog.package(name)
          vcs = package.vcs
          [name, { "url" => vcs.url, "commit" => vcs.commit, "sha256" => vcs.sha256, "commit_time" => package.commit_time,
                   "version" => upstream(package), "tag" => vcs.tag, "branch" => vcs.branch }.compact]
        end
      end
    end
  end
end
