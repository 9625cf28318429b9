# frozen_string_literal: true

require "psych"

require_relative "../catalog"
require_relative "../diagnostic"
require_relative "../error"
require_relative "git_state"

module Relspec
  class Catalog
    # Reads a catalog from a real autoproj workspace with the autoproj gem.
    #
    # AutoprojLoader loads the workspace once per target distribution,
    # because autoproj decides at load time which dependencies are OS
    # packages; it resets autoproj's global state around every load and is
    # patched not to write into the workspace. Commits and commit times come
    # from the checkouts' .git folders.
    class AutoprojSource
      # +distributions+: codename => ReleaseSpec::Distribution, the targets to resolve
      # OS dependencies for.
      # +manifests+: name => manifest.xml text autoproj reads instead of the
      # checkout's (PinnedManifests).
      def self.load(root, distributions, manifests: {})
        new(root, distributions, manifests).load
      end

      def initialize(root, distributions, manifests = {})
        @root = root
        @distributions = distributions
        @manifests = manifests
      end

      def load
        check_workspace
        data = run_loader
        commits = GitState.read(@root, data["packages"].select { |_, p| p["checked_out"] }.transform_values { |p| p["source_dir"] })
        build(data, commits)
      end

      private

      def check_workspace
        config = File.join(@root, ".autoproj", "config.yml")
        return check_config(config) if File.file?(config)

        what = File.directory?(@root) ? "is not an autoproj workspace (no .autoproj/config.yml)" : "does not exist"
        fail_with("not-a-workspace", "#{@root} #{what}",
                  "point `workspace:` at the root of an autoproj workspace or at a catalog snapshot (.yml)")
      end

      # autoproj reads config.yml with YAML.load and lets a syntax error
      # escape as a bare Psych error: say which file, where, before loading.
      def check_config(path)
        document = Psych.parse(File.read(path))
        return if document.nil? || document.root.is_a?(Psych::Nodes::Mapping)

        raise InvalidInput, [Diagnostic.error("workspace-config", ".autoproj/config.yml is not a mapping of autoproj settings",
                                              location: Location.file_only(path),
                                              hint: "fix the file, or run `autoproj reconfigure` in the workspace")]
      rescue Psych::SyntaxError => e
        raise InvalidInput, [Diagnostic.error("workspace-config", "malformed .autoproj/config.yml: #{e.problem}",
                                              location: Location.new(file: path, line: e.line, column: e.column).freeze,
                                              hint: "fix the file, or run `autoproj reconfigure` in the workspace")]
      end

      # autoproj's own messages go to stderr while it loads: relspec's
      # stdout carries data (catalog export writes the snapshot there).
      # The require stays out of the method that rescues AutoprojLoader's
      # errors: an interrupt while autoproj loads (it takes a while) would
      # otherwise evaluate an undefined AutoprojLoader and end as NameError.
      def run_loader
        require_relative "autoproj_loader"
        load_quietly
      end

      def load_quietly
        saved = $stdout
        $stdout = $stderr
        AutoprojLoader.load(File.expand_path(@root), operating_systems, manifests: @manifests)
      rescue AutoprojLoader::WorkspaceProblem => e
        report_problem(e)
      ensure
        $stdout = saved if saved
      end

      def operating_systems
        @distributions.to_h do |codename, distribution|
          [codename, [distribution.osdeps_type_key.split(","), distribution.labels, distribution.ruby_version_keyword]]
        end
      end

      def report_problem(problem)
        file = problem.file && File.expand_path(problem.file, @root)
        file = file.sub("#{File.expand_path(@root)}/", "#{@root}/") if file
        location = file ? Location.new(file: file, line: problem.line, column: problem.line && 1).freeze : Location.file_only(@root)
        raise InvalidInput, [Diagnostic.error(problem.rule, problem.message, location: location, hint: problem.hint)]
      end

      def fail_with(rule, message, hint)
        raise InvalidInput, [Diagnostic.error(rule, message, location: Location.file_only(@root), hint: hint)]
      end

      def build(data, commits)
        packages = data["packages"].to_h do |name, entry|
          commit, time = commits[name]
          vcs = Vcs.from_h(entry.fetch("vcs").merge("commit" => commit || entry["vcs"]["commit"]).compact)
          package = Package.new(
            name: name, package_set: entry["package_set"], build_type: entry["build_type"], vcs: vcs, commit_time: time,
            source_dir: entry["source_dir"], checked_out: entry["checked_out"], version: entry["version"],
            summary: entry["summary"], description: entry["description"], license: entry["license"],
            maintainer: entry["maintainer"], copyright: entry["copyright"], dependencies: entry["dependencies"],
            optional_dependencies: entry["optional_dependencies"], defines: entry["defines"],
            environment: entry["environment"], orogen_arguments: entry["orogen_arguments"],
            extension_task: entry["extension_task"],
            patches: entry.fetch("patches", []).map { |patch| ImportPatch.from_h(patch) },
            os_dependencies: entry["os_dependencies"].transform_values { |deps| OsDependencies.from_h(deps) }
          )
          [name, package]
        end
        Catalog.new(packages: packages, metapackages: data["metapackages"], layout: data["layout"],
                    excluded: data["excluded"], ignored: data["ignored"], codenames: @distributions.keys,
                    exclusion_reasons: data["exclusion_reasons"], weak_metapackages: data["weak_metapackages"])
      end
    end
  end
end
