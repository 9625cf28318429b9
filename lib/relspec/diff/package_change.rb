# frozen_string_literal: true

module Relspec
  module Diff
    # What changed for one package on one target. +kind+ is one of KINDS;
    # +old+ and +new+ are Diff::Decision (nil when added or removed);
    # +commits+ is a CommitRange when the package's source moved;
    # +rebuilt_because+ says why a build got a new Debian revision with the
    # same source (RevisionCause), nil otherwise.
    PackageChange = Struct.new(:package, :kind, :old, :new, :commits, :rebuilt_because, keyword_init: true) do
      # The cause chain that explains the change: the new one when the
      # package is built now, the old one when it stopped being built.
      def causes
        return new.causes if new && !new.causes.empty?

        old ? old.causes : []
      end

      # A build that did not exist before: what a rebuild gate counts.
      def rebuild?
        new&.built? && !(old&.built? && old.version == new.version)
      end

      def with_rebuilt_because(cause)
        PackageChange.new(package: package, kind: kind, old: old, new: new, commits: commits, rebuilt_because: cause).freeze
      end

      def to_h
        { "package" => package, "change" => kind, "old" => old&.to_h, "new" => new&.to_h,
          "commits" => commits&.to_h, "rebuilt_because" => rebuilt_because }.compact
      end
    end

    # The order in which changes are listed, and their names in text.
    KINDS = {
      "inherit_to_build" => "inherit → build",
      "build_to_inherit" => "build → inherit",
      "decision" => "decision changed",
      "added" => "added",
      "removed" => "removed",
      "version" => "version",
      "kept" => "kept (early cutoff)",
      "ancestor" => "other ancestor",
      "cause" => "other cause"
    }.freeze

    # old..new commits of a package's source; +count+ is nil when the
    # repository cannot be read here.
    CommitRange = Struct.new(:from, :to, :count, keyword_init: true) do
      def to_s
        range = "#{from[0, 7]}..#{to[0, 7]}"
        count ? "#{range} (#{count} commit#{'s' unless count == 1})" : range
      end

      def to_h
        { "from" => from, "to" => to, "count" => count }.compact
      end
    end
  end
end
