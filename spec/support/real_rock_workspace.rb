# frozen_string_literal: true

require "fileutils"
require "open3"
require_relative "fixture_workspace"
require "autoproj"

# An autoproj workspace made, offline, from the REAL Rock package sets in
# ../shared/fixtures/rock-repos: rock.core (which imports orocos.toolchain)
# with the layout of rock-core/buildconf (`rock.core`). The package sets are
# cloned where autoproj keeps remote package sets (.autoproj/remotes/<id>),
# so autoproj loads them as it would after `autoproj update`; the packages
# whose repositories are bundled are cloned into src/ and pointed at their
# bundles through autoproj/overrides.yml. Nothing here imitates the package
# sets: what relspec reads is what Rock users load.
#
# Building it takes a few seconds (20 clones): tests share one instance per
# run (RealRockWorkspace.shared) and must not change it.
class RealRockWorkspace
  include FixtureWorkspace

  PACKAGE_SETS = {
    "rock-core/package_set" => "rock-core-package_set",
    "orocos-toolchain/autoproj" => "orocos-toolchain-package_set"
  }.freeze

  # autoproj name => [bundle, folder under src/ (after rock.core's move_package)]
  PACKAGES = {
    "base/cmake" => ["base-cmake", "base/cmake"], "base/logging" => ["base-logging", "base/logging"],
    "base/types" => ["base-types", "base/types"], "base/numeric" => ["base-numeric", "base/numeric"],
    "base/orogen/std" => ["base-orogen-std", "base/orogen/std"],
    "base/orogen/types" => ["base-orogen-types", "base/orogen/types"],
    "utilrb" => ["utilrb", "tools/utilrb"], "utilmm" => ["utilmm", "tools/utilmm"],
    "log4cpp" => ["log4cpp", "tools/log4cpp"], "typelib" => ["tools-typelib", "tools/typelib"],
    "rtt" => ["rtt", "tools/rtt"], "rtt_typelib" => ["tools-rtt_typelib", "tools/rtt_typelib"],
    "orogen" => ["tools-orogen", "tools/orogen"], "tools/metaruby" => ["tools-metaruby", "tools/metaruby"],
    "tools/orogen_metadata" => ["tools-orogen_metadata", "tools/orogen_metadata"],
    "tools/orocos.rb" => ["tools-orocosrb", "tools/orocos.rb"],
    "tools/service_discovery" => ["tools-service_discovery", "tools/service_discovery"],
    "stdint_typekit" => %w[stdint_typekit stdint_typekit],
    # rock.core patches class_loader at import (patches/class_loader_pkgconfig.patch)
    "tools/class_loader" => ["class_loader", "tools/class_loader"],
    "base/console_bridge" => ["base-console_bridge", "base/console_bridge"],
    # needs qtruby, which rock.core's osdeps define for Ubuntu and Gentoo only
    "gui/vizkit" => ["gui-vizkit", "gui/vizkit"]
  }.freeze
  # what autoproj checks out where the repository has no HEAD branch (class_loader: `tag: 0.3.8`)
  CHECKOUTS = { "tools/class_loader" => "0.3.8" }.freeze

  def self.available?
    (PACKAGE_SETS.values + self::PACKAGES.values.map(&:first)).all? { |bundle| File.file?(bundle_path(bundle)) }
  end

  def self.skip_reason
    "the real Rock package sets are not in #{BUNDLES} (../shared/fixtures/rock-repos)"
  end

  def self.bundle_path(bundle)
    File.join(BUNDLES, "#{bundle}.bundle")
  end

  # One workspace per test run, made on first use and removed at exit.
  def self.shared
    @shared ||= begin
      base = Dir.mktmpdir("relspec-real-rock")
      at_exit { FileUtils.rm_rf(base) }
      new(base).tap(&:create)
    end
  end

  def create
    write_configuration(["rock-core/package_set"])
    write("autoproj/overrides.yml", overrides)
    setup = setup_overrides
    write("autoproj/overrides.rb", setup) if setup
    PACKAGE_SETS.each { |github, bundle| git("clone", "-q", self.class.bundle_path(bundle), remote_dir(github)) }
    self.class::PACKAGES.each do |name, (bundle, dir)|
      git("clone", "-q", "--mirror", self.class.bundle_path(bundle), repository(name))
      branch = CHECKOUTS[name] ? ["-b", CHECKOUTS[name]] : []
      git("clone", "-q", "-o", "autobuild", *branch, repository(name), File.join("src", dir))
    end
    root
  end

  # Whether the workspace is there with every package checked out (a DIR
  # kept from a run with other packages is not).
  def complete?
    self.class::PACKAGES.each_value.all? { |(_, dir)| File.directory?(File.join(root, "src", dir)) }
  end

  private

  # This workspace has no SISL (external/sisl is left out where it is built):
  # base/types' CMake stops unless told to do without, so the maintainer says
  # so in the workspace, as autoproj users do.
  def setup_overrides
    <<~RUBY
      setup_package "base/types" do |pkg|
        pkg.define "USE_SISL", "OFF"
      end
    RUBY
  end

  # .autoproj/config.yml and autoproj/ as rock-core/buildconf has them:
  # the manifest loads +package_sets+ (GitHub names) and lays out rock.core.
  def write_configuration(package_sets)
    write(".autoproj/config.yml", <<~YAML)
      source: src
      osdeps_mode: all
      apt_dpkg_update: false
      interactive: false
      USE_OCL: false
      ROCK_SELECTED_FLAVOR: master
    YAML
    sets = package_sets.map { |github| "  - github: #{github}\n" }.join
    write("autoproj/manifest", "package_sets:\n#{sets}layout:\n  - rock.core\n")
    # as rock-core/buildconf's init.rb: the `github:` shorthand of the manifest
    write("autoproj/init.rb", "require 'autoproj/git_server_configuration'\n")
    # orocos.toolchain defines ruby-dev in orocos.osdeps-ruby30 and -ruby32
    # (as `ignore`) but has no -ruby31 file nor -ruby33: on bookworm's
    # Ruby (3.1) and trixie's (3.3) autoproj stops at binding_of_caller's
    # ruby-dev. A Rock maintainer adds the missing definition in the
    # workspace configuration, as here. (autoproj reads
    # <name>.osdeps-ruby<NN> beside an existing <name>.osdeps)
    write("autoproj/workspace.osdeps", "{}\n")
    %w[ruby31 ruby33].each { |ruby| write("autoproj/workspace.osdeps-#{ruby}", "ruby-dev:\n  default: ignore\n") }
  end

  # Where autoproj looks for a remote package set it has checked out:
  # .autoproj/remotes/<repository id with non-word characters as _>, the id
  # autoproj's GITHUB server configuration gives (`github:/<owner>/<name>.git`).
  def remote_dir(github)
    vcs = Autoproj::VCSDefinition.from_raw({ type: "git", url: "https://github.com/#{github}.git",
                                             repository_id: "github:/#{github}.git" })
    File.join(root, ".autoproj", "remotes", vcs.create_autobuild_importer.repository_id.gsub(/[^\w]/, "_"))
  end

  def repository(name)
    File.join(root, "repositories", "#{name.tr('/', '_')}.git")
  end

  def overrides
    "overrides:\n#{self.class::PACKAGES.keys.map { |name| override(name) }.join}"
  end

  # autoproj/overrides.yml's entry pointing +name+ at its repository here.
  def override(name)
    "  - #{name}:\n      type: git\n      url: $AUTOPROJ_ROOT/repositories/#{name.tr('/', '_')}.git\n"
  end

  def git(*args)
    output, status = Open3.capture2e({ "GIT_CONFIG_NOSYSTEM" => "1", "GIT_CONFIG_GLOBAL" => File::NULL },
                                     "git", *args, chdir: root)
    raise "git #{args.join(' ')} failed: #{output}" unless status.success?
  end
end
