# frozen_string_literal: true

require_relative "template"
require_relative "debhelper"
require_relative "naming"
require_relative "environment"

module Relspec
  module Debian
    # debian/rules of one package, from its BuildInput: the dh sequence, the
    # environment of its dependencies, and the body of its build type
    # (templates/rules_<type>.erb) with the words the package sets give
    # the tools.
    class Rules
      Context = Struct.new(:package_name, :build_type, :release, :install_dir, :source, :dependency_dirs,
                           :closure_environment, :dh_options, :body, :cmake_options, :orogen_command, :gem_dir,
                           :gem_file, :canonical, :extension_task, keyword_init: true)
      METHODS = Template.compile(Context, Dir.glob("rules*.erb", base: Template::DIR).sort)

      # What Rock's autoproj configuration gives CMake for a package: its
      # build type, tests off (base/cmake's ROCK_TEST_ENABLED); then the
      # package set's defines (pkg.define, Autobuild::CMake.define, with
      # the prefixes the release gives the packages they name: BuildInput),
      # which win; then the prefix, which the release decides. Each option
      # is one shell word; "$" is doubled for make.
      ROCK_CMAKE_DEFINES = { "CMAKE_BUILD_TYPE" => "Release", "ROCK_TEST_ENABLED" => "OFF" }.freeze

      # The generator's words as autoproj gives them (Catalog::OrogenArguments),
      # quoted as cmake_options are. A package read without them (a snapshot
      # of an older relspec) gets autobuild's defaults; one whose .orogen file
      # was not known when it was read, the one in its source.
      DEFAULT_OROGEN_ARGUMENTS = %w[--corba --transports=corba,mqueue,typelib --type-export-policy=used].freeze

      def initialize(input)
        @in = input
      end

      def rules
        package = @in.package
        shared = { package_name: package.name, build_type: package.build_type, release: @in.release,
                   install_dir: @in.install_dir, source: @in.deb_name }
        body = Template.render(Context, METHODS, "rules_#{kind}.erb", **shared, **body_variables)
        Template.render(Context, METHODS, "rules.erb",
                        **shared, body: body, dependency_dirs: @in.dependency_dirs,
                                  closure_environment: @in.closure_environment.select { |name| BuildInput.variable?(name) },
                                  dh_options: Debhelper.options(package.build_type, @in.debhelper_compat))
      end

      private

      def kind
        kind = @in.package.build_type
        kind == "archive" ? "import" : kind
      end

      def body_variables
        { cmake_options: cmake_options, orogen_command: orogen_command, gem_dir: Environment::GEM_DIR,
          gem_file: @in.gem_file, canonical: Naming.canonical(@in.package.name), extension_task: @in.extension_task }
      end

      def cmake_options
        defines = ROCK_CMAKE_DEFINES.merge(@in.defines)
                                    .merge("CMAKE_INSTALL_PREFIX" => "$(PREFIX)", "CMAKE_INSTALL_LIBDIR" => "lib")
        defines.map do |name, value|
          option = "-D#{name}=#{value}"
          value == "$(PREFIX)" ? option : shell_word(option.gsub("$", "$$"))
        end.join(" ")
      end

      def orogen_command
        words = @in.package.orogen_arguments
        words = DEFAULT_OROGEN_ARGUMENTS if words.empty?
        line = ["orogen", *words.map { |word| shell_word(word.gsub("$", "$$")) }]
        line << "$(wildcard *.orogen)" unless words.last.end_with?(".orogen")
        line.join(" ")
      end

      # One word of a shell line in debian/rules ("$" already doubled for
      # make): a "$" is quoted too, or the shell would expand what make leaves.
      def shell_word(word)
        word.match?(%r{\A[-\w=./:,+]*\z}) ? word : "'#{word.gsub("'", "'\\\\''")}'"
      end
    end
  end
end
