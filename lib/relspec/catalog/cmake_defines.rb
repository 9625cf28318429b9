# frozen_string_literal: true

module Relspec
  class Catalog
    # The -D options autoproj would give CMake for one package: the package
    # sets' global ones (Autobuild::CMake.define), then the package's own
    # (pkg.define); not the prefix and paths autoproj derives from its own
    # layout, which the release decides. A value naming a folder of the
    # workspace is kept relative to $AUTOPROJ_ROOT.
    module CmakeDefines
      module_function

      # Package sets set the global ones while loading: each load starts empty.
      def reset
        Autobuild::CMake.defines.clear
      end

      # +autobuild+: the package after loading; nil when it has none.
      def of(autobuild, root_dir:)
        return nil unless autobuild.respond_to?(:defines)

        defines = Autobuild::CMake.defines.merge(autobuild.defines)
        defines = defines.to_h { |key, value| [key.to_s, value.to_s.gsub(root_dir, "$AUTOPROJ_ROOT")] }
        defines.empty? ? nil : defines.sort.to_h
      end
    end
  end
end
