# frozen_string_literal: true

require "fileutils"
require "open3"
require_relative "fixture_workspace"

# A real autoproj workspace of real Rock packages: the repositories of
# ../shared/fixtures/rock-repos (git bundles of base/cmake, base/logging,
# base/types and utilrb with their history) and the project's own package
# sets, which describe them the way Rock's package sets do:
#
# - orocos.toolchain defines utilrb as a Ruby package, with osdeps for the
#   gems and Debian packages Ruby packages need;
# - rock.core defines the base/ CMake packages, with pkg.define for the
#   options Rock sets (base/types: SISL only when external/sisl is part of
#   the workspace), moves utilrb into tools/ (move_package) and maps the C++
#   OS dependencies (cmake, pkg-config, eigen3, boost, and rice as a gem
#   with Rock's version constraint).
#
# The bundles are third-party code: they stay in ../shared and are cloned
# into the test's temporary folder.
class RockWorkspace
  include FixtureWorkspace

  # autoproj name => [bundle, folder under src/]
  PACKAGES = {
    "base/cmake" => ["base-cmake", "base/cmake"], "base/logging" => ["base-logging", "base/logging"],
    "base/types" => ["base-types", "base/types"], "utilrb" => ["utilrb", "tools/utilrb"]
  }.freeze

  def self.available?
    PACKAGES.values.all? { |bundle, _| File.file?(File.join(BUNDLES, "#{bundle}.bundle")) }
  end

  def self.skip_reason
    "the Rock repository bundles are not in #{BUNDLES} (../shared/fixtures/rock-repos)"
  end

  def create
    write(".autoproj/config.yml", <<~YAML)
      source: src
      osdeps_mode: all
      apt_dpkg_update: false
      interactive: false
    YAML
    write("autoproj/manifest", <<~YAML)
      package_sets:
        - ../package_sets/orocos.toolchain
        - ../package_sets/rock.core
      layout:
        - base/types
        - utilrb
    YAML
    write_orocos_toolchain
    write_rock_core
    PACKAGES.each { |name, (bundle, dir)| clone(name, bundle, dir) }
    root
  end

  private

  def repository(name)
    File.join(root, "repositories", "#{name}.git")
  end

  def clone(name, bundle, dir)
    git(root, "clone", "-q", "--mirror", File.join(BUNDLES, "#{bundle}.bundle"), repository(name))
    git(root, "clone", "-q", "-o", "autobuild", "-b", "master", repository(name), File.join("src", dir))
  end

  def git(dir, *args)
    output, status = Open3.capture2e({ "GIT_CONFIG_NOSYSTEM" => "1", "GIT_CONFIG_GLOBAL" => File::NULL },
                                     "git", *args, chdir: dir)
    raise "git #{args.join(' ')} failed: #{output}" unless status.success?
  end

  # Where autoproj fetches from: every package from the workspace's own
  # mirror of its bundle, on master.
  def source_yml(name, packages)
    entries = packages.map do |package|
      "  - #{package}:\n      type: git\n      url: $AUTOPROJ_ROOT/repositories/#{package}.git\n      branch: master\n"
    end
    "name: #{name}\nversion_control:\n#{entries.join}"
  end

  def write_orocos_toolchain
    dir = "package_sets/orocos.toolchain"
    write("#{dir}/source.yml", source_yml("orocos.toolchain", ["utilrb"]))
    write("#{dir}/toolchain.autobuild", <<~RUBY)
      # The Ruby toolkit of the Orocos toolchain (a gemspec-based package).
      ruby_package 'utilrb'
    RUBY
    # utilrb's manifest names facets (a gem Debian does not package),
    # ruby-backports and bundler; flexmock only for its tests.
    write("#{dir}/orocos.toolchain.osdeps", <<~YAML)
      facets:
        gem: facets
      ruby-backports:
        debian,ubuntu: ruby-backports
      bundler:
        debian,ubuntu: bundler
      flexmock:
        gem: flexmock
    YAML
  end

  def write_rock_core
    dir = "package_sets/rock.core"
    write("#{dir}/source.yml", source_yml("rock.core", %w[base/cmake base/logging base/types]))
    write("#{dir}/base.autobuild", <<~RUBY)
      # Rock's CMake macros, and the libraries built with them.
      cmake_package 'base/cmake'
      cmake_package 'base/logging'

      cmake_package 'base/types' do |pkg|
        # SISL is optional: the spline types are built when external/sisl is
        # a package of this workspace, and base/types' CMake refuses
        # USE_SISL=ON without it.
        sisl = Autoproj.workspace.manifest.find_package_definition('external/sisl')
        pkg.optional_dependency 'external/sisl'
        pkg.define 'USE_SISL', !sisl.nil?
      end

      # Rock keeps the toolchain's Ruby packages under tools/
      move_package 'utilrb', 'tools'
    RUBY
    write("#{dir}/rock.core.osdeps", <<~YAML)
      cmake:
        debian,ubuntu: cmake
      pkg-config:
        debian,ubuntu: pkg-config
      eigen3:
        debian,ubuntu: libeigen3-dev
      boost:
        debian,ubuntu: libboost-system-dev
      # Rock's bindings need the Rice 3 API
      rice:
        gem: rice<4.0.0
    YAML
  end
end
