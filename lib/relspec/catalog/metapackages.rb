# frozen_string_literal: true

require_relative "package"

module Relspec
  class Catalog
    # The metapackages a spec selects by name become packages of their own
    # (build type "meta"): one Debian package depending on the members the
    # release holds, so `apt install <prefix>-<release>-meta-rock.core`
    # installs the set. Its upstream version is made of the newest commit
    # time among its members, so it changes whenever a member does.
    module Metapackages
      module_function

      # +selections+: codename => Selection. Returns [catalog, {codename =>
      # names}] with the metapackages added.
      def add(catalog, select, selections)
        metas = Array(select).select { |name| catalog.metapackage?(name) }.uniq.sort
        return [catalog, selections.transform_values(&:names)] if metas.empty?

        everywhere = selections.values.map(&:names).reduce(:|)
        packages = metas.to_h { |name| [name, meta_package(catalog, name, everywhere)] }
        extended = catalog.with_packages(catalog.packages.merge(packages))
        names = selections.transform_values { |selection| (selection.names + metas).sort.freeze }
        [extended, names]
      end

      def meta_package(catalog, name, selected)
        members = catalog.metapackages.fetch(name) & selected
        times = members.filter_map { |member| catalog.package(member)&.commit_time }
        Package.new(name: name, package_set: nil, build_type: "meta", vcs: Vcs.new(type: "none").freeze,
                    commit_time: times.max, source_dir: nil, version: "0", summary: "metapackage #{name}",
                    description: "The packages of #{name}: #{members.join(', ')}.", dependencies: members)
      end
    end
  end
end
