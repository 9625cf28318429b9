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
    # (beyond the ones every env.sh sets), sorted; +prefixes+: the prefix on the
    # target of each package the package's defines name
    # (Catalog::PrefixMarkers), by autoproj name; one without a decision on
    # the target is missing; +ruby_executable+: the target's Ruby, for a
    # define naming the workspace's (Catalog::CmakeDefines::RUBY). Immutable.
    BuildInput = Struct.new(:package, :deb_name, :upstream, :codename, :release, :maintainer, :install_dir,
                            :debhelper_compat, :dependencies, :apt, :gems, :gem, :ruby_dirs, :closure_tools,
                            :closure_environment, :prefixes, :ruby_executable, keyword_init: true) do
      def initialize(debhelper_compat: BuildInput::DEFAULT_COMPAT, gem: nil, ruby_dirs: [], closure_tools: [],
                     closure_environment: [], prefixes: {}, ruby_executable: "/usr/bin/ruby", **fields)
        super(debhelper_compat: debhelper_compat, gem: gem, ruby_dirs: ruby_dirs, closure_tools: closure_tools,
              closure_environment: closure_environment.dup.freeze, prefixes: prefixes.dup.freeze,
              ruby_executable: ruby_executable, **fields)
        freeze
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
