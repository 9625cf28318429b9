# frozen_string_literal: true

require_relative "../diagnostic"
require_relative "../error"
require_relative "../suggestion"

module Relspec
  class Catalog
    # The packages a release is made of: the spec's `select` (packages and
    # metapackages; default the workspace layout) and, recursively, their
    # dependencies, honouring autoproj's excluded and ignored packages.
    #
    # A package whose OS dependency is `nonexistent` on the codename cannot
    # be built there, and neither can what requires it; autoproj excludes
    # them the same way. The spec's `leave_out` entries work the same way. They are left out of +names+ and kept in
    # +unavailable+ with the reason, so a release can span distributions
    # where part of the stack does not exist.
    class Selection
      attr_reader :names, :roots, :unavailable

      # Why a package is unavailable on the codename: its own +osdeps+
      # marked nonexistent there, the spec's `leave_out` entry that leaves
      # it out (+left_out+: ReleaseSpec::LeaveOut::Entry), or a required
      # +dependency+ that is unavailable itself.
      Unavailable = Struct.new(:osdeps, :left_out, :dependency, keyword_init: true)

      # +select+: names from the spec, or nil for the layout; +codename+: the
      # target whose OS dependencies must all resolve; +locate+: name =>
      # Location of the `select` entry, for messages. Raises InvalidInput.
      # +workspace+: where the catalog came from, for problems of the workspace.
      # +leave_out+: name → the `leave_out` entry that leaves it out on this
      # codename, or nil; such packages are unavailable like those with
      # nonexistent OS dependencies (what requires them too, an optional
      # dependency is dropped), and need no checkout.
      def self.resolve(catalog, select, codename:, workspace:, locate: ->(_name) {}, leave_out: ->(_name) {})
        new(catalog, select, codename, workspace, locate, leave_out)
      end

      def initialize(catalog, select, codename, workspace, locate, leave_out)
        @catalog = catalog
        @codename = codename
        @locate = locate
        @leave_out = leave_out
        @fallback = Location.file_only(workspace)
        @problems = []
        @roots = expand_roots(select || catalog.layout)
        selected = closure(@roots)
        @unavailable = unavailable_among(selected).freeze
        # what only unavailable packages needed is not part of the release there
        @names = @unavailable.empty? ? selected : closure(@roots, skip: @unavailable)
        @names.each { |name| check_buildable(@catalog.package(name)) }
        raise InvalidInput, @problems.uniq unless @problems.empty?

        @names.freeze
        freeze
      end

      def include?(name)
        @names.include?(name)
      end

      def packages
        @names.map { |name| @catalog.package(name) }
      end

      private

      def expand_roots(requested)
        requested.flat_map do |name|
          if @catalog.metapackage?(name)
            @catalog.metapackages[name].reject { |member| dropped?(member) }
          elsif @catalog.package?(name)
            if excluded?(name)
              problem("excluded-package", "#{name} is selected but excluded by the workspace manifest",
                      location: @locate.call(name))
            end
            [name]
          else
            unknown(name)
            []
          end
        end.uniq
      end

      def closure(roots, skip: {})
        seen = {}
        queue = roots.reject { |name| excluded?(name) || ignored?(name) }
        until queue.empty?
          name = queue.shift
          next if seen[name] || skip.key?(name)

          seen[name] = true
          package = @catalog.package(name)
          queue.concat(required(package))
          queue.concat(package.optional_dependencies.reject { |dep| dropped?(dep) || !@catalog.package?(dep) })
        end
        seen.keys.sort
      end

      # Breadth first from the packages with nonexistent OS dependencies
      # along required (not optional) reverse dependencies, so each one
      # names the nearest reason.
      def unavailable_among(selected)
        found = {}
        selected.each do |name|
          if (entry = @leave_out.call(name))
            found[name] = Unavailable.new(left_out: entry).freeze
            next
          end
          missing = @catalog.package(name).os_dependencies_for(@codename).nonexistent
          found[name] = Unavailable.new(osdeps: missing).freeze unless missing.empty?
        end
        frontier = found.keys
        until frontier.empty?
          frontier = selected.reject { |name| found.key?(name) }.filter_map do |name|
            dependency = @catalog.package(name).dependencies.sort.find { |dep| frontier.include?(dep) }
            next unless dependency

            found[name] = Unavailable.new(dependency: dependency).freeze
            name
          end
        end
        found.sort.to_h
      end

      def required(package)
        package.dependencies.filter_map do |dependency|
          next if ignored?(dependency)

          if excluded?(dependency)
            problem("excluded-dependency", "#{package.name} depends on #{dependency}, which the workspace manifest excludes")
          elsif !@catalog.package?(dependency)
            problem("unknown-dependency", "#{package.name} depends on #{dependency}, which the workspace does not define")
          else
            dependency
          end
        end
      end

      def dropped?(name)
        excluded?(name) || ignored?(name)
      end

      def excluded?(name)
        @catalog.excluded.include?(name)
      end

      def ignored?(name)
        @catalog.ignored.include?(name)
      end

      def unknown(name)
        problem("unknown-package", "select names #{name.inspect}, which is neither a package nor a metapackage " \
                                   "of the workspace", hint: Suggestion.hint(name, @catalog.names), location: @locate.call(name))
      end

      # A package the release is made of must have a source and OS
      # dependencies that the target can provide (or knowingly lacks).
      def check_buildable(package)
        unless package.checked_out
          problem("not-checked-out", "#{package.name} is part of the release but not checked out at #{package.source_dir}",
                  hint: "run `autoproj update #{package.name}` in the workspace")
        end
        package.os_dependencies_for(@codename).unresolved.each do |osdep|
          problem("unknown-osdep", "#{package.name} depends on #{osdep.inspect}, which no osdeps file defines for #{@codename}",
                  hint: "add a #{@codename} entry for #{osdep} to a package set's .osdeps file")
        end
      end

      def problem(rule, message, hint: nil, location: nil)
        @problems << Diagnostic.error(rule, message, location: location || @fallback, hint: hint)
        nil
      end
    end
  end
end
