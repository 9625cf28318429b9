# frozen_string_literal: true

require_relative "template"
require_relative "debhelper"
require_relative "environment_file"
require_relative "build_input"
require_relative "../environment_rule"
require_relative "../yaml/writer"

module Relspec
  module Debian
    # What a package installs into its prefix to be used: env.sh (a plain
    # shell's environment), env.yml (autoproj's) and relspec.yml (relspec's
    # own record), from its BuildInput.
    class Environment
      # Where gems install below a package's prefix (GEM_PATH entry). Not
      # lib/ruby/gems: Rock's FindGem.cmake takes every file whose path has
      # "<gem name>…/lib/" as a library of the gem, and a prefix named
      # …-ruby-<gem> followed by /lib/ made it link every sample .so of rice.
      GEM_DIR = "gems"

      Context = Struct.new(:source, :package_name, :release, :guard, :dependency_dirs, :install_dir, :ruby_lib_dirs,
                           :gem_dir, :package_environment, keyword_init: true)
      METHODS = Template.compile(Context, %w[env.sh.erb])

      def initialize(input)
        @in = input
      end

      def env_sh
        source = @in.deb_name
        Template.render(Context, METHODS, "env.sh.erb",
                        source: source, package_name: @in.package.name, release: @in.release,
                        guard: "RELSPEC_ENV_#{source.gsub(/[^A-Za-z0-9]/, '_')}", dependency_dirs: @in.dependency_dirs,
                        install_dir: @in.install_dir, ruby_lib_dirs: ruby_lib_dirs, gem_dir: GEM_DIR,
                        package_environment: package_environment)
      end

      # What the package adds to the environment: one prefix, no dependency
      # (autoproj loads the env.yml of every active package; env.sh, for a
      # plain shell, sources its dependencies itself).
      def env_yml
        dir = @in.install_dir
        variables = { "PATH" => ["#{dir}/bin"], "LD_LIBRARY_PATH" => ["#{dir}/lib"],
                      "PKG_CONFIG_PATH" => ["#{dir}/lib/pkgconfig", "#{dir}/share/pkgconfig"], "CMAKE_PREFIX_PATH" => [dir],
                      "RUBYLIB" => ruby_lib_dirs, "GEM_PATH" => ["#{dir}/#{GEM_DIR}"] }
        EnvironmentFile.render(variables, more: package_environment)
      end

      # relspec's own record of the package (relspec.yml in the prefix): what
      # built it and the prefixes of its dependencies.
      def relspec_yml
        Yaml::Writer.dump({ "package" => @in.package.name, "release" => @in.release, "prefix" => @in.install_dir,
                            "dependencies" => @in.dependency_dirs })
      end

      private

      # What env.sh puts on RUBYLIB. RubyGems activates the highest version
      # of a gem on GEM_PATH wherever it is (this machine has facets 4.0.0 as
      # autoproj's dependency), and activating it for one file rules out the
      # release's version for the next: only RUBYLIB makes the release's
      # version win. A gem of the release: its require paths (facets 3.1.0
      # has lib/core and lib/standard); other packages: <prefix>/lib (a Ruby
      # package's gem links it to its lib/), and for a compiled one also the
      # target Ruby's folders below the prefix, where CMake projects put
      # their bindings (typelib); autoproj adds them for a source-built
      # package when they exist (Autobuild::Environment#add_prefix).
      def ruby_lib_dirs
        gem = @in.gem
        build_type = @in.package.build_type
        unless gem && build_type == "gem"
          compiled = Debhelper.compiled?(build_type) ? @in.ruby_dirs : []
          return ["lib", *compiled].map { |dir| "#{@in.install_dir}/#{dir}" }
        end

        full_name = @in.gem_file.delete_suffix(".gem")
        gem.spec.require_paths.map { |path| "#{@in.install_dir}/#{GEM_DIR}/gems/#{full_name}/#{path}" }
      end

      # The package set's own settings of the package (Catalog::Package#environment)
      # for this prefix: [[type, name, values]]. Only what relspec's package
      # set accepts gets through (EnvironmentRule: a documented variable, a
      # path below the release's prefix or one plain word): a variable it
      # refuses would make it refuse the whole release, a path into the
      # maintainer's workspace ($AUTOPROJ_ROOT) means nothing on a user's
      # machine, and shell syntax would be code in env.sh.
      def package_environment
        @package_environment ||= @in.package.environment.filter_map do |op|
          values = op.fetch("values").map { |value| value.gsub("$PREFIX", @in.install_dir) }
          entry = { type: op.fetch("type").to_sym, values: values }
          next if values.any? { |value| value.match?(/["$`\\\n]/) }
          next if EnvironmentRule.problem(op.fetch("name"), entry, prefix: File.dirname(@in.install_dir))

          [op.fetch("type"), op.fetch("name"), values]
        end
      end
    end
  end
end
