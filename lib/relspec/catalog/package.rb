# frozen_string_literal: true

require_relative "vcs"
require_relative "os_dependencies"
require_relative "import_patch"

module Relspec
  class Catalog
    # One autoproj package as relspec needs it, independent of autoproj.
    #
    # +commit_time+ is the UTC commit time of the checked-out commit as
    # "YYYY-MM-DDTHH:MM:SSZ" (the upstream version is derived from it);
    # +os_dependencies+ maps a distribution codename to OsDependencies.
    class Package
      BUILD_TYPES = %w[cmake orogen autotools ruby python import archive meta gem].freeze

      FIELDS = %i[name package_set build_type vcs commit_time version summary description license maintainer
                  copyright source_dir checked_out dependencies optional_dependencies os_dependencies defines
                  environment orogen_arguments extension_task patches].freeze

      attr_reader(*FIELDS)

      def initialize(name:, package_set:, build_type:, vcs:, commit_time:, source_dir:, checked_out: true, version: nil,
                     summary: nil, description: nil, license: nil, maintainer: nil, copyright: [], dependencies: [],
                     optional_dependencies: [], os_dependencies: {}, defines: {}, environment: [],
                     orogen_arguments: [], extension_task: nil, patches: [])
        @name = name
        @package_set = package_set
        @build_type = build_type
        @vcs = vcs
        @commit_time = commit_time
        @version = version
        @summary = summary
        @description = description
        @license = license
        @maintainer = maintainer
        # the upstream copyright holders (manifest.xml), "Name <email>"
        @copyright = (copyright || []).dup.freeze
        @source_dir = source_dir
        @checked_out = checked_out
        @dependencies = dependencies.uniq.sort.freeze
        @optional_dependencies = optional_dependencies.uniq.sort.freeze
        @os_dependencies = os_dependencies.sort.to_h.freeze
        @build_dependencies = (@dependencies + @optional_dependencies).uniq.sort.freeze
        # CMake -D options of the package set (pkg.define), name => value
        @defines = (defines || {}).sort.to_h.freeze
        # the package set's environment settings of the package, in order:
        # [{"type" => set|add|add_path, "name", "values" (with $PREFIX)}]
        @environment = (environment || []).map(&:freeze).freeze
        # an oroGen package's generator words, as autoproj gives them
        # (Catalog::OrogenArguments); empty for other build types
        @orogen_arguments = (orogen_arguments || []).dup.freeze
        # a Ruby package's rake task that compiles its C extension
        # (Catalog::RubyExtension); nil for other packages
        @extension_task = extension_task&.dup.freeze
        # the package set's import patches (ImportPatch), in the order autoproj applies them
        @patches = (patches || []).map { |patch| patch.is_a?(ImportPatch) ? patch.freeze : ImportPatch.from_h(patch) }.freeze
        freeze
      end

      # Every package of the workspace this one needs when it is built.
      attr_reader :build_dependencies

      def os_dependencies_for(codename)
        os_dependencies.fetch(codename, OsDependencies::EMPTY)
      end

      def with(**changes)
        self.class.new(**FIELDS.to_h { |field| [field, public_send(field)] }, **changes)
      end

      def ==(other)
        other.is_a?(Package) && to_h == other.to_h
      end
      alias eql? ==

      def hash
        to_h.hash
      end

      def to_h
        {
          "package_set" => package_set, "build_type" => build_type, "vcs" => vcs.to_h,
          "commit_time" => commit_time, "version" => version, "summary" => summary, "description" => description,
          "license" => license, "maintainer" => maintainer, "copyright" => copyright, "source_dir" => source_dir,
          "checked_out" => checked_out ? nil : false,
          "dependencies" => dependencies, "optional_dependencies" => optional_dependencies,
          "os_dependencies" => os_dependencies.transform_values(&:to_h), "defines" => defines,
          "environment" => environment, "orogen_arguments" => orogen_arguments, "extension_task" => extension_task,
          "patches" => patches.map(&:to_h)
        }.reject { |_key, value| value.nil? || value == [] || value == {} }
      end

      def self.from_h(name, hash)
        new(
          name: name, package_set: hash["package_set"], build_type: hash["build_type"],
          vcs: Vcs.from_h(hash.fetch("vcs", {})), commit_time: hash["commit_time"], version: hash["version"],
          summary: hash["summary"], description: hash["description"], checked_out: hash.fetch("checked_out", true), license: hash["license"], maintainer: hash["maintainer"],
          copyright: hash.fetch("copyright", []),
          source_dir: hash["source_dir"], dependencies: hash.fetch("dependencies", []),
          optional_dependencies: hash.fetch("optional_dependencies", []),
          os_dependencies: hash.fetch("os_dependencies", {}).transform_values { |deps| OsDependencies.from_h(deps) },
          defines: hash.fetch("defines", {}), environment: hash.fetch("environment", []),
          orogen_arguments: hash.fetch("orogen_arguments", []), extension_task: hash["extension_task"],
          patches: hash.fetch("patches", []).map { |patch| ImportPatch.from_h(patch) }
        )
      end
    end
  end
end
