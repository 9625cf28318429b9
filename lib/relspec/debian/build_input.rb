# frozen_string_literal: true

module Relspec
  module Debian
    # What the debian/ of one build is made from (DebianDir's input), as the
    # plan decided it on one target: the catalog +package+, its +deb_name+
    # and +upstream+ version, the target's +codename+ and +debhelper_compat+
    # level, the release's name and +maintainer+, the prefix it installs into
    # (+install_dir+), its +dependencies+ (Dependency, in the package's
    # order), its OS dependencies resolved for the codename (+apt+ names,
    # distribution +gems+ as ruby-<gem>) and, for a gem of the release, the
    # +gem+ archive (nil otherwise), and +ruby_dirs+: where the target's Ruby
    # would have a compiled package install Ruby code, relative to the
    # prefix (Distribution#ruby_install_dirs), and +closure_tools+: the
    # build-only tools of its whole dependency closure
    # (ControlRelations.build_only), sorted; +closure_environment+: the
    # variables the package sets' environment settings of that closure name
    # (beyond the ones every env.sh sets), sorted; +defines+: the package
    # set's CMake defines of the package ({name => value}, in its order) as
    # the plan resolved them for the target: a reference to another
    # package's prefix is that package's prefix on the target, a define
    # naming a package without a decision there is left out;
    # +extension_task+: the checked rake task that compiles a Ruby
    # package's extension (Catalog::RubyExtension), or nil. Immutable.
    BuildInput = Struct.new(:package, :deb_name, :upstream, :codename, :release, :maintainer, :install_dir,
                            :debhelper_compat, :dependencies, :apt, :gems, :gem, :ruby_dirs, :closure_tools,
                            :closure_environment, :defines, :extension_task, keyword_init: true) do
      def initialize(debhelper_compat: BuildInput::DEFAULT_COMPAT, gem: nil, ruby_dirs: [], closure_tools: [],
                     closure_environment: [], defines: {}, extension_task: nil, **fields)
        super(debhelper_compat: debhelper_compat, gem: gem, ruby_dirs: ruby_dirs, closure_tools: closure_tools,
              closure_environment: closure_environment.dup.freeze, defines: defines.dup.freeze,
              extension_task: extension_task, **fields)
        freeze
      end

      # The prefixes of the dependencies built by Rock releases (the
      # distribution's own packages live in the system).
      def dependency_dirs
        dependencies.filter_map(&:install_dir)
      end

      # The file name of the release's gem archive, nil for other packages.
      def gem_file
        gem && "#{gem.name}-#{gem.version}.gem"
      end
    end

    # BuildInput's constants and checks.
    class BuildInput
      # debhelper's compat level when the target's is not known (the
      # distributions' table, compile.md, always knows it).
      DEFAULT_COMPAT = 13

      # What every env.sh sets, which debian/rules always takes.
      STANDARD_VARIABLES = %w[PATH CMAKE_PREFIX_PATH PKG_CONFIG_PATH LD_LIBRARY_PATH RUBYLIB GEM_PATH].freeze

      # A variable name debian/rules may carry from the dependencies' env.sh:
      # a plain shell name (it reaches a make and a shell line), not one of
      # the standard ones.
      def self.variable?(name)
        name.is_a?(String) && name.match?(/\A[A-Za-z_][A-Za-z0-9_]*\z/) && !STANDARD_VARIABLES.include?(name)
      end

      # A dependency as debian/ names it: Debian name, the version the plan
      # decided (text), and the prefix it installs into (nil: a package of
      # the distribution, in the system).
      Dependency = Struct.new(:deb_name, :version, :install_dir, keyword_init: true) do
        def initialize(**fields)
          super
          freeze
        end
      end
    end
  end
end
