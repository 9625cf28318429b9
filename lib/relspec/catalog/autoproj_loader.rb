# frozen_string_literal: true

# Loads one autoproj workspace once per target distribution with the real
# autoproj gem, offline and read-only, into plain data. Required only when a
# workspace is read, so commands that do not read one never load autoproj.
#
# autoproj keeps process-global state (registered packages, Rake tasks, the
# current workspace): it is reset before and after every load. It also has
# to be patched not to write into the workspace (ReadOnlyConfiguration).
require "autoproj"
require "tmpdir"
require_relative "autoproj_messages"
require_relative "copyright_holders"
require_relative "package_environment"
require_relative "orogen_arguments"
require_relative "ruby_extension"
require_relative "cmake_defines"
require_relative "prefix_markers"
require_relative "import_patch"
require_relative "autoproj_osdeps"

module Relspec
  class Catalog
    # Loads an autoproj workspace in-process (its manifest, package sets and
    # package manifests) the way autoproj itself would, for the catalog.
    module AutoprojLoader
      # Raised for workspace problems a user must fix; printed as a diagnostic.
      class WorkspaceProblem < StandardError
        attr_reader :rule, :file, :line, :hint

        def initialize(rule, message, file: nil, line: nil, hint: nil)
          super(message)
          @rule = rule
          @file = file
          @line = line
          @hint = hint
        end
      end

      # Package managers that can neither install nor prompt: a read-only load
      # must never touch the system.
      class InertPackageManager < Autoproj::PackageManagers::Manager
        def initialize_environment; end

        def configure_manager; end

        def install(*)
          raise WorkspaceProblem.new("workspace-write", "autoproj tried to install OS packages while reading the workspace")
        end
      end

      # autoproj writes into a workspace while loading it even with
      # read_only: true: it deletes unused folders in .autoproj/remotes,
      # (re)creates autoproj/remotes symlinks, creates .test-results folders,
      # and would clone missing package sets. These patches make it read only.
      module ReadOnlyConfiguration
        def update_remote_package_set(vcs, **)
          return if File.exist?(Autoproj::PackageSet.raw_local_dir_of(ws, vcs))

          raise WorkspaceProblem.new("missing-package-set", "package set #{vcs.url} is not checked out",
                                     hint: "run `autoproj update` in the workspace first")
        end

        def cleanup_remotes_dir(*); end

        def cleanup_remotes_user_dir(*); end

        def create_remote_set_user_dir(vcs)
          File.join(remotes_user_dir, Autoproj::PackageSet.name_of(ws, vcs))
        end
      end

      # A workspace bootstrapped with another Ruby records it in config.yml;
      # that matters for building, not for reading.
      module AnyRubyConfiguration
        def validate_ruby_executable; end
      end

      # Package sets do file work in post_import blocks (rock.core's rtt block
      # deletes a stale generated file from the checkout). The blocks run
      # for what they declare (dependencies, defines, options); inside them
      # FileUtils' writing methods do nothing, so a load stays read only.
      module QuietFileWrites
        WRITERS = %i[rm rm_f rm_r rm_rf remove_file remove_dir mkdir mkdir_p makedirs cp cp_r mv ln ln_s ln_sf touch
                     install chmod chmod_R chown].freeze

        WRITERS.each do |writer|
          define_method(writer) do |*args, **options, &block|
            Thread.current[:relspec_quiet_file_writes] ? nil : super(*args, **options, &block)
          end
        end
      end

      BUILD_TYPES = {
        "Autobuild::Orogen" => "orogen", "Autobuild::CMake" => "cmake", "Autobuild::Autotools" => "autotools",
        "Autobuild::Ruby" => "ruby", "Autobuild::Python" => "python", "Autobuild::ImporterPackage" => "import"
      }.freeze

      module_function

      # Loads +root+ once per target into plain data. Every problem of the
      # workspace, autoproj's included, is raised as a WorkspaceProblem.
      # +manifests+: package name => manifest.xml text read instead of the
      # checkout's (a pinned commit's, see PinnedManifests).
      def load(root, targets, manifests: {})
        install_patches
        on_stderr do
          Dir.mktmpdir("relspec-manifests") do |dir|
            files = manifests.to_h do |name, text|
              path = File.join(dir, "#{name.tr('/', '_')}.xml")
              File.write(path, text)
              [name, path]
            end
            load_all(root, targets, files)
          end
        end
      rescue Autoproj::ConfigError, Autoproj::PackageNotFound, Autobuild::Exception, Autoproj::InputError => e
        raise autoproj_problem(e)
      rescue ArgumentError => e
        # autoproj reports a package set folder that does not exist this way
        raise unless (missing = e.message[/'([^']+)' is neither a remote source specification, nor an existing local directory/, 1])

        raise WorkspaceProblem.new("missing-package-set", "package set #{missing} does not exist", file: "autoproj/manifest",
                                                                                                   hint: "check `package_sets:` in autoproj/manifest, or run `autoproj update`")
      ensure
        reset_global_state
      end

      # autobuild's progress display writes to STDOUT (with terminal escape
      # codes): relspec's stdout is its output (JSON, plans), so autoproj's
      # messages are collected while it loads and go to stderr, each once
      # (AutoprojMessages).
      def on_stderr
        previous = Autobuild.instance_variable_get(:@display)
        messages = AutoprojMessages.new
        Autobuild.instance_variable_set(:@display, AutoprojMessages::Display.new(messages))
        yield
      ensure
        Autobuild.instance_variable_set(:@display, previous)
        $stderr.write(messages.to_s)
      end

      def autoproj_problem(error)
        message = error.message.strip
        if (invalid = message.match(/invalid (\S+manifest\.xml): (.*)/m))
          line = invalid[2][/Line: (\d+)/, 1]&.to_i
          reason = invalid[2].lines.first.strip
          return WorkspaceProblem.new("package-manifest", "broken manifest.xml: #{reason}", file: invalid[1], line: line,
                                                                                            hint: "fix the XML of the package's manifest.xml")
        end
        WorkspaceProblem.new("autoproj", message.lines.first(6).join.strip, hint: "autoproj could not load the workspace")
      end

      def install_patches
        return if Autoproj::Ops::Configuration.include?(ReadOnlyConfiguration)

        Autoproj::Ops::Configuration.prepend(ReadOnlyConfiguration)
        Autoproj::Configuration.prepend(AnyRubyConfiguration)
        # autoproj's DSL helper creates <srcdir>/.test-results; keep the rest of it.
        FileUtils.singleton_class.prepend(QuietFileWrites)
        Object.send(:define_method, :ruby_package_default_test_task) do |pkg|
          pkg.with_tests if pkg.test_utility.source_dir
        end
      end

      # +targets+: codename => [[type names], [labels], ruby keyword or nil]
      def load_all(root, targets, manifests)
        per_target = targets.to_h { |codename, os| [codename, load_one(root, os, manifests)] }
        first = per_target.values.first
        packages = first[:packages].to_h do |name, package|
          os = per_target.to_h { |codename, loaded| [codename, loaded[:os_dependencies].fetch(name)] }
          [name, package.merge("os_dependencies" => os)]
        end
        first[:workspace].merge("packages" => packages)
      end

      def load_one(root, operating_system, manifests)
        reset_global_state
        types, labels, ruby_keyword = operating_system
        resolver = Autoproj::OSPackageResolver.new(operating_system: [types, labels])
        managers = Autoproj::OSPackageInstaller::PACKAGE_MANAGERS.keys.to_h { |name| [name, InertPackageManager] }
        ws = Autoproj::Workspace.from_dir(root, os_package_resolver: resolver, package_managers: managers)
        # the target's Ruby, not relspec's, picks the .osdeps-ruby<NN> files
        # and what the `ruby` osdep means
        ws.ruby_version_keyword = ruby_keyword if ruby_keyword
        ws.config.interactive = false
        ws.setup(read_only: true, load_global_configuration: false)
        # autoproj maps the `ruby` osdep to ruby31 on Ruby 3.1, which its own
        # default.osdeps does not define.
        resolver.add_entries({ ws.ruby_version_keyword => "ignore" }) unless resolver.include?(ws.ruby_version_keyword)
        ws.load_package_sets(only_local: true, checkout_only: true)
        AutoprojOsdeps.warn_spaced_keys(resolver)
        ws.setup_all_package_directories
        markers = PrefixMarkers.new(ws.manifest.each_autobuild_package.to_a, prefix_dir: ws.prefix_dir)
        markers.while_marked do
          ws.finalize_package_setup
          ws.manifest.each_package_definition do |definition|
            if manifests[definition.name]
              load_manifest_file(ws, definition, manifests[definition.name])
            elsif definition.checked_out?
              ws.manifest.load_package_manifest(definition.name)
            end
          end
          run_post_import_blocks(ws)
        end
        ws.finalize_setup(read_only: true)
        extract(ws, manifests, markers)
      ensure
        ws&.clear_main_workspace
      end

      # What autoproj runs after importing each package that is checked out,
      # neither excluded nor ignored (Ops::Import): the package sets'
      # post_import blocks, which add dependencies (typelib's C++ importer,
      # castxml) and settings. A block may exclude a package itself.
      def run_post_import_blocks(ws)
        manifest = ws.manifest
        Thread.current[:relspec_quiet_file_writes] = true
        manifest.each_package_definition do |definition|
          next unless definition.checked_out?
          next if manifest.excluded?(definition.name) || manifest.ignored?(definition.name)

          Autoproj.each_post_import_block(definition) { |block| block.call(definition.autobuild) }
        end
      ensure
        Thread.current[:relspec_quiet_file_writes] = nil
      end

      # What Manifest#load_package_manifest does, from another file: the
      # package's description and the dependencies it declares.
      def load_manifest_file(ws, definition, path)
        definition.autobuild.description =
          Autoproj::PackageManifest.load(definition.autobuild, path, ros_manifest: false, condition_context: ws.config)
        definition.apply_dependencies_from_manifest
      end

      def reset_global_state
        Autobuild::Package.clear
        Autoproj.post_import_blocks.clear
        Rake::Task.clear
        Autoproj.workspace = nil
        Autobuild.env = nil
        # package sets set project-wide build settings in autobuild's classes
        CmakeDefines.reset
        OrogenArguments.reset
      end

      def extract(ws, manifests, markers)
        manifest = ws.manifest
        packages = {}
        os_dependencies = {}
        # every osdep name is resolved once per load, however many packages use it
        resolved = Hash.new { |cache, name| cache[name] = AutoprojOsdeps.classify(ws.os_package_resolver, name) }
        manifest.each_package_definition do |definition|
          packages[definition.name] = package_data(ws, definition, markers)
          # a pinned commit's manifest is named as the checkout's file, not the temporary copy
          packages[definition.name]["manifest"] = relative(ws, File.join(definition.autobuild.srcdir, "manifest.xml")) if manifests[definition.name]
          os_dependencies[definition.name] = os_dependencies_of(definition.autobuild, resolved)
        end
        { packages: packages, os_dependencies: os_dependencies, workspace: workspace_data(manifest) }
      end

      # Mandatory OS dependencies, and the optional ones kept as autoproj
      # keeps them (import.rb: an optional dependency is added unless it is
      # excluded, and an osdep the OS cannot provide is excluded). The ones
      # left out are listed under "optional_missing", for plan's notes.
      def os_dependencies_of(autobuild, resolved)
        _, optional = autobuild.partition_optional_dependencies
        optional -= autobuild.os_packages.to_a
        kept, missing = optional.partition { |name| !resolved[name].keys.intersect?(%w[nonexistent other_os unresolved]) }
        merged = merge_classified((autobuild.os_packages.to_a + kept).sort.map { |name| resolved[name] })
        merged["optional_missing"] = missing.sort unless missing.empty?
        merged
      end

      def workspace_data(manifest)
        metapackages = {}
        manifest.each_metapackage do |meta|
          next if meta.name.include?(" ") # autoproj's "main configuration" pseudo package sets

          metapackages[meta.name] = meta.each_package.map(&:name).sort
        end
        {
          "metapackages" => metapackages, "layout" => manifest.normalized_layout.keys,
          # the manifest's exclusions and the package sets' (add_exclusion)
          "excluded" => manifest.each_excluded_package.map(&:name).sort,
          "ignored" => manifest.each_ignored_package.map(&:name).sort,
          "exclusion_reasons" => manifest.each_excluded_package.to_h { |pkg| [pkg.name, manifest.exclusion_reason(pkg.name)] },
          # metapackages whose unavailable members are dropped rather than an error (Metapackage#weak_dependencies?)
          "weak_metapackages" => manifest.each_metapackage.select(&:weak_dependencies?).map(&:name).sort
        }
      end

      def package_data(ws, definition, markers)
        autobuild = definition.autobuild
        optional_packages, = autobuild.partition_optional_dependencies
        {
          "package_set" => definition.package_set.name, "build_type" => build_type(autobuild),
          "vcs" => vcs_data(ws, definition.vcs), "source_dir" => relative(ws, autobuild.srcdir),
          "checked_out" => definition.checked_out?, "dependencies" => autobuild.dependencies.sort,
          "optional_dependencies" => optional_packages.sort,
          "defines" => CmakeDefines.of(autobuild, root_dir: ws.root_dir, markers: markers, ruby: ws.config.ruby_executable),
          "environment" => PackageEnvironment.of(autobuild, root_dir: ws.root_dir, markers: markers),
          "orogen_arguments" => OrogenArguments.of(autobuild), "extension_task" => RubyExtension.setup_task(autobuild),
          "patches" => ImportPatch.list_of(autobuild.importer) { |path| relative(ws, path) }
        }.compact.merge(manifest_data(ws, autobuild.description))
      end

      def build_type(autobuild)
        return "archive" if autobuild.importer.is_a?(Autobuild::ArchiveImporter)

        BUILD_TYPES.fetch(autobuild.class.name) do
          BUILD_TYPES.find { |class_name, _| autobuild.class.ancestors.map(&:name).include?(class_name) }&.last || "import"
        end
      end

      def vcs_data(ws, vcs)
        url = vcs.url.to_s
        # Paths inside the workspace are written relative to it, so the
        # catalog does not depend on where the workspace lives.
        url = url.sub(ws.root_dir, "$AUTOPROJ_ROOT") if url.start_with?("#{ws.root_dir}/")
        { "type" => vcs.type.to_s, "url" => url, "branch" => vcs.options[:branch], "tag" => vcs.options[:tag],
          "commit" => vcs.options[:commit] }.compact
      end

      def manifest_data(ws, description)
        return {} if description.nil? || description.null?

        maintainers = description.each_maintainer.map { |name, email| email ? "#{name} <#{email}>" : name }
        {
          "version" => description.version, "summary" => description.brief_description,
          "description" => description.description&.strip, "license" => description.license,
          "maintainer" => maintainers.empty? ? nil : maintainers.join(", "),
          "copyright" => CopyrightHolders.of(description.path, description.each_author.to_a,
                                             description.each_maintainer.to_a).then { |holders| holders.empty? ? nil : holders },
          "manifest" => relative(ws, description.path)
        }.compact
      end

      def relative(ws, path)
        path.to_s.delete_prefix("#{ws.root_dir}/")
      end

      def merge_classified(parts)
        merged = Hash.new { |hash, key| hash[key] = [] }
        parts.each { |part| part.each { |kind, names| merged[kind].concat(names) } }
        merged.transform_values { |names| names.uniq.sort }
      end
    end
  end
end
