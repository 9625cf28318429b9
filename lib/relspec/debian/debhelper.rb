# frozen_string_literal: true

module Relspec
  module Debian
    # What the target's debhelper compat level decides in debian/, and
    # which build system dh is told to use (debian/control and debian/rules
    # both depend on it).
    module Debhelper
      # debhelper-compat in Build-Depends needs debhelper 11.1.4; older ones
      # read debian/compat.
      BUILD_DEPENDS_COMPAT = 11

      # debhelper runs dh_autoreconf by itself from compat 10 on; before
      # (xenial's 9) it is an add-on of its own package.
      AUTORECONF_BY_DEFAULT = 10

      # dh's options per build type; the types listed compile code.
      BUILDSYSTEMS = { "cmake" => " --buildsystem=cmake", "orogen" => " --buildsystem=cmake",
                       "autotools" => " --buildsystem=autoconf" }.freeze

      module_function

      # The Build-Depends entry of debhelper itself.
      def relation(compat)
        compat_file?(compat) ? "debhelper (>= #{compat})" : "debhelper-compat (= #{compat})"
      end

      # Whether the level goes into debian/compat (not into Build-Depends).
      def compat_file?(compat)
        compat < BUILD_DEPENDS_COMPAT
      end

      # An autotools package on a debhelper that needs the autoreconf add-on.
      def old_autotools?(build_type, compat)
        build_type == "autotools" && compat < AUTORECONF_BY_DEFAULT
      end

      # Build-Depends the add-on needs.
      def autoreconf(build_type, compat)
        old_autotools?(build_type, compat) ? ["dh-autoreconf"] : []
      end

      # The options of `dh $@`.
      def options(build_type, compat)
        BUILDSYSTEMS.fetch(build_type, "") + (old_autotools?(build_type, compat) ? " --with autoreconf" : "")
      end

      # Whether a package of +build_type+ compiles code.
      def compiled?(build_type)
        BUILDSYSTEMS.key?(build_type)
      end
    end
  end
end
