# frozen_string_literal: true

require_relative "../target"

module Relspec
  module Plan
    Target = Relspec::Target
  end
end
