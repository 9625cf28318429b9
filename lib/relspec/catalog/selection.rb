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
    # A package whose OS dependency is `nonexistent` on the codename, or
    # defined for other systems only, cannot be built there, nor can a
    # package autoproj excludes, nor what requires one of them; autoproj
    # excludes them the same way, and the spec's `leave_out` entries work
    # the same way. They are left out of +names+ and kept in +unavailable+
    # with the reason, so a release can span distributions where part of
    # the stack does not exist.
    #
    # As in autoproj (PackageSelection#filter_excluded_and_ignored_packages),
    # selecting a package that is unavailable because of an exclusion or
    # an OS dependency of other systems is an error, and so is selecting a
    # metapackage with such a member unless the metapackage is weak
    # (`weak_dependencies`, as the rock package set's `rock`). The spec's
    # `leave_out` and osdeps' `nonexistent` are statements about a
    # distribution: what they remove is a gap, never an error.
    class Selection
      attr_reader :names, :roots, :unavailable

      # Why a package is unavailable on the codename: its own +osdeps+
      # marked nonexistent there, its +other_os+ osdeps (defined for other
      # systems only), its exclusion by autoproj (+excluded+: the reason), the
      # spec's `leave_out` entry that leaves it out (+left_out+:
      # ReleaseSpec::LeaveOut::Entry), or a required +dependency+ that is
      # unavailable itself.
      Unavailable = Struct.new(:osdeps, :left_out, :dependency, :excluded, :other_os, keyword_init: true) do
        # Whether autoproj refuses to build a selection needing it (a
        # `leave_out` or a nonexistent osdep is a gap of the distribution).
        def refused?
          !excluded.nil? || !Array(other_os).empty?
        end
      end

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
        requested = select || catalog.layout
        @roots = expand_roots(requested)
        selected = closure(@roots)
        @unavailable = unavailable_among(selected).freeze
        requested.each { |name| check_requested(name, select ? "selected" : "in the layout") }
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
            # excluded members stay: they are unavailable, and an error in a strong metapackage
            @catalog.metapackages[name].reject { |member| ignored?(member) }
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
        queue = roots.reject { |name| ignored?(name) }
        until queue.empty?
          name = queue.shift
          next if seen[name] || skip.key?(name)

          seen[name] = true
          # what only a left-out or excluded package needs is not part of the release
          next if @leave_out.call(name) || excluded?(name)

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
          if excluded?(name)
            found[name] = Unavailable.new(excluded: @catalog.exclusion_reasons[name] || "excluded by autoproj").freeze
            next
          end
          os = @catalog.package(name).os_dependencies_for(@codename)
          next if os.nonexistent.empty? && os.other_os.empty?

          found[name] = Unavailable.new(osdeps: os.nonexistent.empty? ? nil : os.nonexistent,
                                        other_os: os.other_os.empty? ? nil : os.other_os).freeze
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

          if @catalog.package?(dependency)
            dependency
          else
            problem("unknown-dependency", "#{package.name} depends on #{dependency}, which the workspace does not define")
          end
        end
      end

      # autoproj's rule for a selection whose packages cannot be built here.
      def check_requested(name, how)
        if @catalog.metapackage?(name)
          members = @catalog.metapackages[name].reject { |member| ignored?(member) }
          refused = members.select { |member| refused?(member) }
          return if refused.empty? || (@catalog.weak?(name) && refused.size < members.size)

          refused.each do |member|
            problem("unavailable-selection", "#{name} is #{how}, but its package #{member} cannot be built on " \
                                             "#{@codename}: #{explain(member)}",
                    location: @locate.call(name), hint: metapackage_hint(name, refused.size == members.size))
          end
        elsif @catalog.package?(name) && !excluded?(name) && refused?(name)
          problem("unavailable-selection", "#{name} is #{how}, but cannot be built on #{@codename}: #{explain(name)}",
                  location: @locate.call(name), hint: "select what needs it instead, or leave it out (`leave_out`)")
        end
      end

      def metapackage_hint(name, all)
        return "every package of #{name} is unavailable here: leave them out (`leave_out`)" if all

        "autoproj refuses this too, unless #{name} has weak dependencies; select its other packages, or leave " \
          "these out (`leave_out`)"
      end

      def refused?(name)
        reason = @unavailable[name]
        reason = @unavailable[reason.dependency] while reason&.dependency
        reason&.refused? || false
      end

      # "it requires a, which requires b, which is excluded (reason)"
      def explain(name)
        steps = []
        reason = @unavailable.fetch(name)
        while reason.dependency
          steps << "requires #{reason.dependency}"
          reason = @unavailable.fetch(reason.dependency)
        end
        root = if reason.excluded then "is excluded (#{reason.excluded})"
               else "needs the osdep #{reason.other_os.join(', ')}, which the osdeps files define for other systems only"
               end
        "it #{(steps + [root]).join(', which ')}"
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
