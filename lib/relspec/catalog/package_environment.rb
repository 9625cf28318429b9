# frozen_string_literal: true

module Relspec
  class Catalog
    # The environment settings a package set gives one package (pkg.env_set,
    # env_add_path, env_add: typelib's TYPELIB_PLUGIN_PATH), in their order,
    # as Catalog::Package#environment keeps them: the package's workspace
    # prefix is written $PREFIX (the release puts its own), another folder of
    # the workspace $AUTOPROJ_ROOT. What autoproj derives from the prefix
    # itself (add_prefix: PATH, PKG_CONFIG_PATH, ...) the release writes
    # anyway; a package set's workspace-wide env_set is not the package's.
    module PackageEnvironment
      TYPES = %i[set add add_path].freeze

      module_function

      # +autobuild+: the Autobuild::Package after loading; +markers+: the
      # PrefixMarkers of the load (a prefix read while they were set is
      # autoproj's again). nil when it has none.
      def of(autobuild, root_dir:, markers:)
        operations = autobuild.env.select { |op| TYPES.include?(op.type) && op.values.all?(String) }
        return nil if operations.empty?

        prefix = autobuild.prefix.to_s
        operations.map do |op|
          values = op.values.map { |value| markers.restore(value).gsub(prefix, "$PREFIX").gsub(root_dir, "$AUTOPROJ_ROOT") }
          { "type" => op.type.to_s, "name" => op.name.to_s, "values" => values }
        end
      end
    end
  end
end
