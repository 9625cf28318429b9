# frozen_string_literal: true

module Relspec
  # Base of every error meant for a person: the CLI prints its message without
  # a backtrace. Anything else that escapes is a bug in relspec.
  class Error < StandardError; end

  # Input was rejected; carries the diagnostics that say why.
  class InvalidInput < Error
    attr_reader :diagnostics

    def initialize(diagnostics)
      @diagnostics = diagnostics.sort_by(&:sort_key).freeze
      super(@diagnostics.map(&:to_s).join("\n"))
    end
  end
end
