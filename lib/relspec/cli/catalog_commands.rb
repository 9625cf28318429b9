# frozen_string_literal: true

require "thor"
require_relative "../printable"
require_relative "strict_commands"
require "json"

module Relspec
  module CLI
    # `relspec catalog …`: the package database of a workspace.
    class CatalogCommands < Thor
      include StrictCommands

      namespace "catalog"

      def self.exit_on_failure?
        true
      end

      desc "export WORKSPACE", "Write a catalog snapshot of an autoproj workspace (YAML, deterministic)"
      long_desc <<~TEXT
        Loads the workspace with autoproj (offline, read-only) once per target
        distribution and writes the whole catalog: packages, sources, commits,
        dependencies and OS dependencies per distribution. A spec's `workspace:`
        may point to such a file, so that CI can plan without the workspace.
      TEXT
      option :targets, type: :string, desc: "Distribution codenames, comma separated (default: every built-in one)"
      option :output, aliases: "-o", type: :string, desc: "Write to this file (atomically) instead of stdout"
      def export(workspace)
        require_relative "../release_specs/distribution"
        require_relative "../catalog/autoproj_source"
        require_relative "../catalog/snapshot_source"
        catalog = Catalog::AutoprojSource.load(workspace, ReleaseSpec::Distributions.builtin(options[:targets]))
        return Catalog::SnapshotSource.write(options[:output], catalog) if options[:output]

        $stdout.write(Catalog::SnapshotSource.dump(catalog))
      end

      desc "show SPEC", "List the packages of a release per target distribution"
      option :target, type: :string, desc: "Only this distribution codename"
      option :format, enum: %w[text json], default: "text", desc: "Output format"
      def show(path)
        require_relative "../release_specs"
        require_relative "../catalog/release_catalog"
        release = Catalog::ReleaseCatalog.load(ReleaseSpec.resolve(path))
        selections = release.selections_on(options[:target])
        options[:format] == "json" ? $stdout.puts(JSON.pretty_generate(as_json(release, selections))) : print_text(release, selections)
      end

      private

      def as_json(_release, selections)
        selections.to_h do |codename, selection|
          [codename, selection.packages.to_h { |package| [package.name, package.to_h.slice("build_type", "vcs", "commit_time", "version")] }]
        end
      end

      def print_text(release, selections)
        selections.each do |codename, selection|
          puts "#{codename}: #{selection.names.size} packages from #{release.workspace}"
          selection.packages.each do |package|
            commit = package.vcs.commit ? package.vcs.commit[0, 10] : package.vcs.tag || package.vcs.branch
            puts format("  %-32s %-9s %-10s %s", package.name, package.build_type, commit, package.commit_time)
          end
          selection.unavailable.each do |name, reason|
            why =
              if reason.dependency then "requires #{reason.dependency}"
              elsif reason.left_out then "left out by #{Printable.text(reason.left_out.pattern.source)} (#{Printable.text(reason.left_out.reason)})"
              elsif reason.excluded then "excluded by autoproj: #{Printable.text(reason.excluded)}"
              elsif reason.osdeps.nil? then "osdeps #{Printable.text(reason.other_os.join(', '))} defined for other systems only"
              else "osdeps #{reason.osdeps.join(', ')} nonexistent"
              end
            puts format("  %-32s unavailable on #{codename}: %s", name, why)
          end
        end
      end
    end
  end
end
