# frozen_string_literal: true

require_relative "source"
require_relative "pinning"
require_relative "pinned_manifests"
require_relative "selection"
require_relative "metapackages"
require_relative "release_gems"
require_relative "gem_resolution"
require_relative "archive_import"
require_relative "../cache_dir"
require_relative "../display_path"
require_relative "../release_specs/package_pattern"
require_relative "../suggestion"

module Relspec
  class Catalog
    # The catalog of one release: its workspace read for the release's
    # target distributions, its pins applied, the metapackages it selects by
    # name added as packages, the gems of `gems:` added as packages, and the
    # names of the selected packages (with dependencies) for each target
    # codename. +gems+: gem name => GemArchive; +gem_resolution+: the
    # GemResolution::Result (gems packaged without `gems:`).
    class ReleaseCatalog
      attr_reader :catalog, :selections, :workspace, :gems, :gem_resolution

      # The selections of the target codename +codename+ only (nil: all).
      def selections_on(codename)
        return selections unless codename
        raise InvalidOption, "#{codename} is not a target codename of this release (#{selections.keys.join(', ')})" \
          unless selections.key?(codename)

        selections.slice(codename)
      end

      # The selected names on one codename, with their packages, and the
      # selected packages that cannot exist there (name => Selection::Unavailable).
      Selected = Struct.new(:names, :catalog, :unavailable) do
        def packages
          names.map { |name| catalog.package(name) }
        end
      end

      # +resolution+: a valid ReleaseSpec::Resolution; +cache+: a Catalog::Cache
      # for catalogs read from workspaces, or nil; +gem_fetch+: (name,
      # version) → GemArchive (default: from the spec's gem_source);
      # +gem_archives+: a Plan::GemArchives (#call: target name => {ruby-*
      # name => versions}, nil for a target without an archive; #depends:
      # target name => {gem package => GemDepends}), read only when the
      # release has gems to resolve; without it (catalog show) only `gems:`
      # are packaged. +locked_gems+: name => the version the lock recorded.
      # Raises InvalidInput.
      def self.load(resolution, cache: nil, gem_fetch: nil, gem_archives: nil, locked_gems: {}, timeout: 10)
        spec_file = resolution.spec_file
        effective = resolution.effective
        workspace = workspace_path(spec_file, effective)
        distributions = effective.distributions.slice(*effective.targets.keys)
        catalog = Source.load(workspace, distributions, cache: cache)
        root = SnapshotSource.snapshot?(workspace) ? nil : workspace
        pins = effective.pins
        # a pinned commit declares its own dependencies: load again with its manifest
        manifests = root ? PinnedManifests.of(catalog, pins, root) : {}
        catalog = Source.load(workspace, distributions, cache: cache, manifests: manifests) unless manifests.empty?
        pinned = Pinning.apply(catalog, pins, root: root,
                                              locate: ->(name) { effective.pin_origin(name)&.location })
        selections = select_all(pinned, effective, spec_file, workspace)
        pinned = import_archives(pinned, selections, timeout)
        catalog, names = Metapackages.add(pinned, effective.select, selections)
        gem_fetch ||= ReleaseGems.fetcher(effective, File.dirname(resolution.spec_file.path), timeout: timeout)
        resolved = resolve_gems(catalog, names, resolution, gem_fetch, gem_archives, locked_gems, timeout)
        catalog, names, gems = add_gems(catalog, names, resolution, gem_fetch, resolved)
        new(catalog, names, selections.transform_values(&:unavailable), workspace, gems, resolved)
      end

      # Archive imports of the release get their archive's time and
      # checksum (ArchiveImport): their version is made of them.
      def self.import_archives(catalog, selections, timeout)
        names = selections.values.flat_map(&:names).uniq.select { |name| catalog.package(name).build_type == "archive" }
        return catalog if names.empty?

        import = ArchiveImport.new(cache: CacheDir.for("archives"), timeout: timeout)
        catalog.with_packages(catalog.packages.merge(names.to_h { |name| [name, import.resolve(catalog.package(name))] }))
      end

      def self.workspace_path(spec_file, effective)
        path = effective.workspace
        unless path
          raise InvalidInput, [Diagnostic.error("missing-workspace", "release #{effective.release} names no workspace",
                                                location: spec_file.location(["release"]),
                                                hint: "add `workspace:` (an autoproj workspace or a catalog snapshot)")]
        end
        DisplayPath.of(File.expand_path(path, File.dirname(spec_file.path)))
      end

      def self.select_all(catalog, effective, spec_file, workspace)
        select = effective.select
        locate = lambda do |name|
          index = select&.index(name)
          index ? spec_file.location(["select", index]) : nil
        end
        problems = []
        leave_out = effective.leave_out
        problems.concat(unmatched_leave_out(catalog, leave_out, effective))
        selections = effective.targets.keys.sort.to_h do |codename|
          [codename, Selection.resolve(catalog, select, codename: codename, workspace: workspace, locate: locate,
                                                        leave_out: ->(name) { leave_out.match(name, codename) })]
        rescue InvalidInput => e
          problems.concat(e.diagnostics)
          [codename, nil]
        end
        raise InvalidInput, problems.uniq(&:to_s) unless problems.empty?

        selections
      end

      # A `leave_out` entry that matches no package of the workspace is a
      # typo or a stale entry, as an unmatched blacklist entry is.
      def self.unmatched_leave_out(catalog, leave_out, effective)
        origin = effective.origin("leave_out")
        leave_out.entries.reject { |entry| catalog.names.any? { |name| entry.pattern.match?(name) } }.map do |entry|
          Diagnostic.error("unmatched-leave-out", "leave_out entry #{entry.pattern.source.inspect} matches no package of the workspace",
                           location: origin&.file&.location(origin.path + [entry.index, "match"]),
                           hint: Suggestion.hint(entry.pattern.source, catalog.names) || "remove the entry, or fix the match")
        end
      end

      def self.resolve_gems(catalog, names, resolution, fetch, archives, locked, timeout)
        return GemResolution::NONE unless archives

        effective = resolution.effective
        spec_dir = File.dirname(resolution.spec_file.path)
        blacklist = effective.blacklist
        selected = names.to_h { |codename, list| [codename, list.select { |name| catalog.package?(name) }] }
        GemResolution.new(catalog: catalog, selected: selected, pinned: effective.gems, archives: archives,
                          depends: archives.method(:depends),
                          locked: locked, versions: GemVersions.new(effective.gem_source, base_dir: spec_dir, timeout: timeout),
                          fetch: fetch, blacklisted: ->(name) { blacklist.any? { |entry| entry.match?(name) } },
                          location: effective.origin("gem_source")&.location || resolution.spec_file.location(["release"]),
                          rubies: TargetRubies.of(effective), locate: ->(name) { effective.entry_location("gems", name) })
                     .call
      end

      def self.add_gems(catalog, names, resolution, fetch, resolved)
        effective = resolution.effective
        locate = ->(name) { effective.entry_location("gems", name) }
        gems = effective.gems.merge(resolved.automatic)
        ReleaseGems.add(catalog, gems, names, fetch: fetch, locate: locate, provided: resolved.provided)
      end

      private_class_method :workspace_path, :select_all, :resolve_gems, :add_gems, :import_archives

      def initialize(catalog, names, unavailable, workspace, gems, gem_resolution = GemResolution::NONE)
        @catalog = catalog
        @gems = gems.freeze
        @gem_resolution = gem_resolution
        @selections = names.to_h { |codename, list| [codename, Selected.new(list, catalog, unavailable.fetch(codename)).freeze] }.freeze
        @workspace = workspace
        freeze
      end
    end
  end
end
