# frozen_string_literal: true

require "json"

module Relspec
  module Report
    # The Page for tools: the data of the HTML page, as a versioned document
    # (docs/report.md).
    module JsonRenderer
      module_function

      def render(page)
        "#{JSON.pretty_generate(page.to_h)}\n"
      end
    end
  end
end
