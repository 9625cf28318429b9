# frozen_string_literal: true

module Relspec
  module Diff
    # Why a package built on both sides got a new Debian revision while its
    # own source did not change (same upstream version): the planner gives a
    # new revision when the package's Debian inputs change, and the usual
    # reason is a dependency that changed version. Without this, the diff
    # showed a bare "-1 → -2" with the cause chain of the build itself,
    # which says why the package is built, not why it is built again.
    module RevisionCause
      # When no dependency changed. A lock that records the build's
      # dependencies (+depends+) rules them out; an older one does not, so
      # the other changes of the target are then only candidates.
      INPUTS = "its Debian inputs changed (a dependency, the release's settings or the packaging"
      # (debian/ names only the direct dependencies, each with the folder it
      # is installed in, which follows its release's prefixes and which the
      # lock does not record; the rest of the closure is found through their
      # installed env.sh at build time, so it is not an input)
      SETTINGS = "its Debian inputs changed (the release's settings, the packaging or where a direct dependency " \
                 "is installed; none of its direct dependencies changed)"
      # Candidates named before "and N more".
      CANDIDATES = 3

      module_function

      # The cause, in words, of +change+'s new revision, or nil when the
      # change is not a revision bump of a build. +changes+: the target's
      # PackageChanges by package.
      def of(change, changes)
        return nil unless revision_bump?(change)

        # a change of cause chain only is not in debian/
        moved = dependencies(change).filter_map { |name| changes[name] }.reject { |other| other.kind == "cause" }
        reasons = moved.map { |dependency| moved(dependency) }
        reasons << relisted(change) if recorded?(change) && !change.old.depends.nil? && change.old.depends != change.new.depends
        return reasons.join("; ") unless reasons.empty?

        recorded?(change) ? SETTINGS : inputs(change, changes)
      end

      def recorded?(change)
        !change.new.depends.nil?
      end

      # "its dependencies changed (now also base/logging; no longer base/cmake)"
      def relisted(change)
        added = change.new.depends - change.old.depends
        removed = change.old.depends - change.new.depends
        parts = []
        parts << "now also #{added.join(', ')}" unless added.empty?
        parts << "no longer #{removed.join(', ')}" unless removed.empty?
        "its dependencies changed (#{parts.join('; ')})"
      end

      # "its Debian inputs changed (…; changed on this target and maybe among
      # its dependencies: base/logging)"
      def inputs(change, changes)
        # Other revision bumps are consequences (dependents), not candidates.
        others = changes.values.select do |other|
          other.package != change.package && !revision_bump?(other) &&
            (other.old&.version != other.new&.version || other.old&.deb != other.new&.deb)
        end.map(&:package).sort
        return "#{INPUTS})" if others.empty?

        shown = others.first(CANDIDATES)
        shown << "#{others.size - CANDIDATES} more" if others.size > CANDIDATES
        "#{INPUTS}; changed on this target and maybe among its dependencies: #{shown.join(', ')})"
      end

      def revision_bump?(change)
        change.kind == "version" && change.old.built? && change.new.built? &&
          upstream(change.old.version) == upstream(change.new.version)
      end

      # The version without its Debian revision (after the last "-").
      def upstream(version)
        version.to_s.rpartition("-").first
      end

      # The packages that can have moved the package's Debian inputs: those
      # the lock records (every one that changed is named), else those the
      # cause chains name as dependencies (the nearest one only, since the
      # chain is not the whole list).
      def dependencies(change)
        return change.new.depends if recorded?(change)

        (change.new.causes + change.old.causes).filter_map do |step|
          step.delete_prefix("depends on ").split(",", 2).first if step.start_with?("depends on ")
        end.uniq.first(1)
      end

      # "base/types changed version (2.0.20200302.140000-1~bionic → 2.0.20200601.103000-1~bionic)"
      def moved(dependency)
        old = dependency.old&.version
        new = dependency.new&.version
        return "#{dependency.package} changed version (#{old} → #{new})" if old && new && old != new

        "#{dependency.package} changed (#{KINDS.fetch(dependency.kind)})"
      end
    end
  end
end
