# frozen_string_literal: true

require_relative "naming"
require_relative "gem_relations"

module Relspec
  module Debian
    # The relationship fields of a generated debian/control: Build-Depends
    # and Depends of one package, from its build type, its OS dependencies
    # (apt names and distribution gems) and the relations to other Rock
    # packages. Control writes them; the availability check (relspec check)
    # asks for the same lists without the Rock packages, so that what is
    # checked is exactly what the builder will ask apt for.
    module ControlRelations
      # oroGen's generator asks pkg-config for every library and typekit it
      # uses (using_library, import_types_from), and so does its CMake: no
      # package it depends on brings pkg-config to a clean chroot (BUILD_ONLY).
      BUILD_TOOLS = { "cmake" => ["cmake"], "orogen" => %w[cmake pkg-config], "autotools" => %w[autoconf automake libtool],
                      "ruby" => %w[ruby git], "gem" => ["ruby"], "import" => [], "archive" => [], "meta" => [] }.freeze

      # build-essential is implied for every build (and Policy forbids listing it).
      IMPLIED = %w[build-essential].freeze

      # Build tools autoproj adds as OS dependencies of every cmake or
      # autotools package; a built package does not need them to run.
      BUILD_ONLY = %w[cmake autoconf automake libtool pkg-config ruby-dev].freeze

      DEBHELPER = "debhelper-compat (= 13)"

      # What autoproj installs for itself in every workspace (its bootstrap
      # osdeps: Ruby with its headers), so every CMake build autoproj runs
      # finds them: base/cmake's RockRuby (rock_ruby_library, used by
      # tools/orogen_metadata, typelib's and base/types' bindings) stops at
      # `Could NOT find Ruby` without ruby-dev. A clean chroot has neither.
      AUTOPROJ_OWN = { "cmake" => ["ruby-dev"], "orogen" => ["ruby-dev"] }.freeze

      module_function

      # What a package's users need at their own build time that its
      # Depends leaves out: the build-only tools among its build type's and
      # its OS dependencies. A package that uses base/cmake's macros (which
      # call pkg-config) or an oroGen typekit (found with pkg-config) needs
      # them as autoproj would have installed them: the osdeps of the whole
      # dependency closure before building.
      def build_only(build_type, apt)
        (BUILD_TOOLS.fetch(build_type, []) + apt) & BUILD_ONLY
      end

      # The distribution's ruby-<gem> packages for the gems of an
      # OsDependencies that the release does not package itself
      # (+release_gems+: the names it packages), with the entry's version
      # constraint as Debian relations ("rice<4.0.0" → "ruby-rice (<< 4.0.0)").
      def distribution_gems(os_dependencies, release_gems)
        os_dependencies.gems.flat_map do |entry|
          gem = Naming.gem_name(entry)
          release_gems.include?(gem) ? [] : GemRelations.of(Naming.distribution_gem(gem), entry.delete_prefix(gem))
        end.uniq
      end

      # The OS part of the relations: apt names, then distribution gems.
      def os_relations(apt, distribution_gems)
        (apt - IMPLIED) + distribution_gems
      end

      # +own+: relations to Rock packages ("name (>= version)"), written first.
      # +debhelper+: the relation naming the target's debhelper compat level.
      # +closure+: the build-only tools of the package's dependency closure
      # (#build_only of each), written last.
      def build_depends(build_type, own, os, debhelper: DEBHELPER, closure: [])
        return [debhelper] if build_type == "meta"

        ([debhelper] + BUILD_TOOLS.fetch(build_type, []) + own + os + closure +
         AUTOPROJ_OWN.fetch(build_type, [])).uniq
      end

      # What a gem that ships headers for other code (GemArchive#ships_headers?)
      # needs at run time, although it is a build tool elsewhere: its headers
      # include Ruby's.
      HEADER_GEM = %w[ruby-dev].freeze

      # +architecture+: "any" adds the shlibs substitution variable.
      def depends(build_type, architecture, own, os, ships_headers: false)
        base = architecture == "any" ? ["${shlibs:Depends}", "${misc:Depends}"] : ["${misc:Depends}"]
        base += ["ruby"] if %w[ruby gem].include?(build_type)
        (base + ((own + os) - BUILD_ONLY) + (ships_headers ? HEADER_GEM : [])).uniq
      end
    end
  end
end
