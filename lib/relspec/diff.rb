# frozen_string_literal: true

require_relative "diff/input"
require_relative "diff/base_comparison"
require_relative "diff/release_diff"
require_relative "diff/text_renderer"
require_relative "diff/markdown_renderer"
require_relative "diff/json_renderer"

module Relspec
  # Release diffs for review (DESIGN §1, §7): what a change to specs/, the
  # workspace or an ancestor does to each release, per target, and why.
  module Diff
    FORMATS = %w[text markdown json].freeze

    module_function

    # +diffs+ (ReleaseDiffs) in +format+; +color+ only for text.
    def render(diffs, format, color: false)
      case format
      when "markdown" then MarkdownRenderer.new.render(diffs)
      when "json" then JsonRenderer.render(diffs)
      else TextRenderer.new(color: color).render(diffs)
      end
    end
  end
end
