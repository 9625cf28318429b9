# frozen_string_literal: true

require_relative "../plan/source_record"

module Relspec
  module Diff
    # One package's decision on one target, as the diff sees it: the kind
    # ("inherit", "build", "published", "system", "unavailable"), the Debian
    # name and version, the ancestor it comes from, the cause chain and, for
    # builds, the packages its debian/ names (+depends+; nil when the lock
    # predates that record). +depends+ is not compared: it only explains.
    # +kept+: why the early cutoff kept a published version (docs/abi.md).
    Decision = Struct.new(:kind, :deb, :version, :from, :causes, :depends, :kept, keyword_init: true) do
      def built?
        %w[build published].include?(kind)
      end

      def inherited?
        kind == "inherit"
      end

      # The package whose own cause (blacklist, pin, …) started the chain:
      # the last "depends on X" step, or +package+ itself.
      def root_package(package)
        step = causes.reverse.find { |line| line.start_with?("depends on ") }
        step ? step.delete_prefix("depends on ").split(",", 2).first : package
      end

      # The original cause at the end of the chain.
      def root_cause
        causes.last
      end

      def to_h
        { "decision" => kind, "deb" => deb, "version" => version, "from" => from,
          "causes" => causes.empty? ? nil : causes, "kept" => kept }.compact
      end
    end

    # Where a package's source comes from (url, commit, …): the lock's own
    # typed record, compared field by field (SourceChange).
    PackageSource = Plan::SourceRecord

    # Everything a diff compares of one release: its name, where it was read
    # (+source+, as the user named it), the spec digest, per ancestor and
    # codename the digest of what it provides, the package sources, per
    # target ("codename/arch") package => Decision, and the spec file's own
    # data (+spec+, nil when not known) for spec-level changes; +workspace+:
    # the autoproj workspace of a spec read from disk (where the sources'
    # git repositories are, to count commits), nil otherwise; +stale+: the
    # lock this side would have been read from, when it was out of date and
    # the side was planned instead (nil: read from +source+ as it is);
    # +edited+: SourceChanges from the plan to what that lock records (a
    # lock edited by hand to point a package elsewhere), or nil.
    Snapshot = Struct.new(:release, :source, :spec_digest, :ancestors, :packages, :targets, :spec, :workspace, :stale,
                          :edited, keyword_init: true) do
      def self.empty(release, source)
        new(release: release, source: source, spec_digest: nil, ancestors: {}, packages: {}, targets: {}, spec: nil).freeze
      end

      # +spec_dir+: the folder of a spec file on disk (its workspace: is
      # relative to it); nil for a spec read from git.
      def with_spec(spec, spec_dir: nil)
        workspace = spec_dir && spec["workspace"].is_a?(String) ? File.expand_path(spec["workspace"], spec_dir) : nil
        Snapshot.new(**to_h, spec: spec, workspace: workspace && File.directory?(workspace) ? workspace : nil).freeze
      end

      def with_source(source)
        Snapshot.new(**to_h, source: source).freeze
      end
    end
  end
end
