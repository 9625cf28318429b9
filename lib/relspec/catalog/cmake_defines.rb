# frozen_string_literal: true

module Relspec
  class Catalog
    # The -D options autoproj would give CMake for one package: the package
    # sets' global ones (Autobuild::CMake.define), then the package's own
    # (pkg.define); not the prefix and paths autoproj derives from its own
    # layout, which the release decides. Another package's prefix in a value
    # becomes a reference to that package (PrefixMarkers), which the release
    # replaces with the prefix it gives the package; another folder of the
    # workspace is kept relative to $AUTOPROJ_ROOT.
    module CmakeDefines
      module_function

      # Package sets set the global ones while loading: each load starts empty.
      def reset
        Autobuild::CMake.defines.clear
      end

      # +autobuild+: the package after loading; +markers+: the PrefixMarkers
      # of the load. nil when it has none.
      def of(autobuild, root_dir:, markers:)
        return nil unless autobuild.respond_to?(:defines)

        defines = Autobuild::CMake.defines.merge(autobuild.defines)
        defines = defines.to_h { |key, value| [key.to_s, markers.references(value.to_s).gsub(root_dir, "$AUTOPROJ_ROOT")] }
        defines.empty? ? nil : defines.sort.to_h
      end
    end
  end
end
