# frozen_string_literal: true

require_relative "catalog/package"

module Relspec
  # The package database of a release's workspace (docs/catalog.md): every package
  # with its source, dependencies and per-distribution OS dependencies, the
  # metapackages and the layout (the default selection). Built by
  # Catalog::AutoprojSource from a workspace or Catalog::SnapshotSource from
  # a `relspec catalog export` file; immutable.
  class Catalog
    attr_reader :packages, :metapackages, :layout, :excluded, :ignored, :codenames, :exclusion_reasons,
                :weak_metapackages

    # +packages+: name => Package; +metapackages+: name => [package names];
    # +layout+: the names autoproj builds by default; +excluded+/+ignored+:
    # autoproj's exclude_packages / ignore_packages and the package sets'
    # exclusions; +exclusion_reasons+: excluded name => autoproj's reason;
    # +weak_metapackages+: the metapackages whose unavailable members are
    # dropped instead of being an error; +codenames+: the distributions the
    # OS dependencies were resolved for.
    def initialize(packages:, metapackages: {}, layout: [], excluded: [], ignored: [], codenames: [],
                   exclusion_reasons: {}, weak_metapackages: [])
      @packages = packages.sort.to_h.freeze
      @metapackages = metapackages.sort.to_h { |name, members| [name, members.sort.freeze] }.freeze
      @layout = layout.dup.freeze
      @excluded = excluded.sort.freeze
      @ignored = ignored.sort.freeze
      @codenames = codenames.sort.freeze
      @exclusion_reasons = exclusion_reasons.compact.sort.to_h.freeze
      @weak_metapackages = weak_metapackages.sort.freeze
      freeze
    end

    # The same catalog with other packages (pins applied, gems or
    # metapackages added).
    def with_packages(packages)
      self.class.new(packages: packages, metapackages: metapackages, layout: layout, excluded: excluded, ignored: ignored,
                     codenames: codenames, exclusion_reasons: exclusion_reasons, weak_metapackages: weak_metapackages)
    end

    def weak?(metapackage)
      weak_metapackages.include?(metapackage)
    end

    def package(name)
      packages[name]
    end

    def package?(name)
      packages.key?(name)
    end

    def metapackage?(name)
      metapackages.key?(name)
    end

    # Every name a spec may mention in `select`, `pins` or `blacklist`.
    def names
      (packages.keys + metapackages.keys).sort
    end

    def ==(other)
      other.is_a?(Catalog) && to_h == other.to_h
    end

    def to_h
      {
        "codenames" => codenames, "layout" => layout, "excluded" => excluded, "ignored" => ignored,
        "exclusion_reasons" => exclusion_reasons, "weak_metapackages" => weak_metapackages,
        "metapackages" => metapackages, "packages" => packages.transform_values(&:to_h)
      }.reject { |key, value| %w[exclusion_reasons weak_metapackages].include?(key) && value.empty? }
    end
  end
end
