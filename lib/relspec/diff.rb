# frozen_string_literal: true

require_relative "diff/input"
require_relative "diff/base_comparison"
require_relative "diff/release_diff"
require_relative "diff/text_renderer"
require_relative "diff/markdown_renderer"
require_relative "diff/json_renderer"
require_relative "diff/abi_section"
require_relative "project"
require_relative "error"

module Relspec
  # Release diffs for review (docs/diff.md): what a change to specs/, the
  # workspace or an ancestor does to each release, per target, and why.
  module Diff
    FORMATS = %w[text markdown json].freeze

    # Compares the project in the current folder when --base names no spec.
    PROJECT_ROOT = "."

    module_function

    # `relspec diff`: the ReleaseDiffs of OLD and NEW (+paths+: two lock
    # files, release folders or specs), or with +base+ (a git revision) of
    # each spec in +paths+ (none: every spec of the project) against its
    # state at +base+. Specs are planned (+timeout+: HTTP timeout).
    def run(paths:, base:, timeout:)
      planner = lambda do |path|
        require_relative "plan" # planning loads most of relspec: only when a spec must be planned
        Plan.run(path, timeout: timeout).lock
      end
      pairs = base ? base_pairs(paths, base, planner) : [snapshots(paths, planner)]
      pairs.map { |old, new| ReleaseDiff.compare(old, new) }
    end

    def snapshots(paths, planner)
      raise Error, "relspec diff needs OLD and NEW (lock files, release folders or specs), or --base REF" unless paths.size == 2

      paths.map { |path| Input.snapshot(path, planner: planner) }
    end

    def base_pairs(paths, base, planner)
      roots = paths.map { |path| Project.of_spec(path).root }.uniq
      raise Error, "the specs given belong to different projects: #{roots.join(', ')}" if roots.size > 1

      names = paths.empty? ? nil : paths.map { |path| File.basename(path, ".yml") }
      BaseComparison.new(roots.first || PROJECT_ROOT, base, planner: planner).pairs(names)
    end
    private_class_method :snapshots, :base_pairs

    # +diffs+ (ReleaseDiffs) in +format+; +color+ only for text. +abi+:
    # release => Abi::Report (AbiSection) shown by markdown and json.
    def render(diffs, format, color: false, abi: {})
      case format
      when "markdown" then MarkdownRenderer.new.render(diffs) + abi.values.map { |report| "\n#{report.render('markdown')}" }.join
      when "json" then JsonRenderer.render(diffs, abi: abi)
      else TextRenderer.new(color: color).render(diffs)
      end
    end
  end
end
