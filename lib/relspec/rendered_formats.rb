# frozen_string_literal: true

require "json"

module Relspec
  # The one `--format text|markdown|json` switch of the reports relspec
  # prints (check, abi, mirror): the includer gives #text, #markdown and
  # #to_h; JSON is always the same pretty form of #to_h.
  module RenderedFormats
    def render(format)
      case format
      when "json" then "#{JSON.pretty_generate(to_h)}\n"
      when "markdown" then markdown
      else text
      end
    end
  end
end
