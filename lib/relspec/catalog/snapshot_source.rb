# frozen_string_literal: true

require_relative "../catalog"
require_relative "../yaml/writer"
require_relative "../yaml/located_document"
require_relative "../error"
require_relative "../atomic_file"
require_relative "snapshot_shape"

module Relspec
  class Catalog
    # A catalog written to YAML (`relspec catalog export`) so that CI can plan
    # a release without the workspace. The file is deterministic: keys in a
    # fixed order, packages sorted, no timestamps or host paths.
    module SnapshotSource
      FORMAT_KEY = "relspec_catalog"
      FORMAT_VERSION = 1

      module_function

      def dump(catalog)
        Yaml::Writer.dump({ FORMAT_KEY => FORMAT_VERSION }.merge(catalog.to_h))
      end

      # The snapshot of +catalog+ at +path+, replaced by rename.
      def write(path, catalog)
        AtomicFile.write(path, dump(catalog))
      end

      def snapshot?(path)
        File.file?(path) && path.end_with?(".yml", ".yaml")
      end

      def load(path)
        document = Yaml::LocatedDocument.load(path)
        raise InvalidInput, document.diagnostics unless document.ok?

        data = document.data
        unless data.is_a?(Hash) && data[FORMAT_KEY] == FORMAT_VERSION
          raise InvalidInput, [Diagnostic.error("catalog-format", "#{path} is not a relspec catalog snapshot " \
                                                                  "(format #{FORMAT_VERSION})",
                                                location: document.location([]),
                                                hint: "write one with `relspec catalog export WORKSPACE > #{path}`")]
        end
        problems = SnapshotShape.problems(data, document)
        raise InvalidInput, problems unless problems.empty?

        build(data)
      end

      def build(data)
        packages = data.fetch("packages", {}).to_h { |name, entry| [name, Package.from_h(name, entry)] }
        Catalog.new(packages: packages, metapackages: data.fetch("metapackages", {}), layout: data.fetch("layout", []),
                    excluded: data.fetch("excluded", []), ignored: data.fetch("ignored", []),
                    codenames: data.fetch("codenames", []), exclusion_reasons: data.fetch("exclusion_reasons", {}),
                    weak_metapackages: data.fetch("weak_metapackages", []))
      end
    end
  end
end
