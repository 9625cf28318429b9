# frozen_string_literal: true

module Relspec
  class Catalog
    # The -D options autoproj would give CMake for one package: the package
    # sets' global ones (Autobuild::CMake.define), then the package's own
    # (pkg.define); not the prefix and paths autoproj derives from its own
    # layout, which the release decides. Another package's prefix in a value
    # becomes a reference to that package (PrefixMarkers), which the release
    # replaces with the prefix it gives the package; another folder of the
    # workspace is kept relative to $AUTOPROJ_ROOT. The Ruby the workspace
    # was loaded with (rock.core's `pkg.define "RUBY_EXECUTABLE",
    # Autoproj.config.ruby_executable`: relspec's own, /usr/bin/ruby3.1)
    # becomes ${ruby}, which the release replaces with the target's Ruby
    # (trixie builds with ruby3.3, which has no /usr/bin/ruby3.1).
    module CmakeDefines
      RUBY = "${ruby}"

      module_function

      # Package sets set the global ones while loading: each load starts empty.
      def reset
        Autobuild::CMake.defines.clear
      end

      # +autobuild+: the package after loading; +markers+: the PrefixMarkers
      # of the load; +ruby+: the workspace's Ruby executable (nil: none
      # known). nil when it has none.
      def of(autobuild, root_dir:, markers:, ruby: nil)
        return nil unless autobuild.respond_to?(:defines)

        defines = Autobuild::CMake.defines.merge(autobuild.defines)
        defines = defines.to_h do |key, value|
          [key.to_s, ruby_reference(markers.references(value.to_s), ruby).gsub(root_dir, "$AUTOPROJ_ROOT")]
        end
        defines.empty? ? nil : defines.sort.to_h
      end

      # +value+ with the Ruby executable (a whole path, not the start of a
      # longer one) written ${ruby}
      def ruby_reference(value, ruby)
        return value if ruby.to_s.empty?

        value.gsub(%r{(?<![\w./+-])#{Regexp.escape(ruby)}(?![\w./+-])}, RUBY)
      end
    end
  end
end
