# frozen_string_literal: true

module Relspec
  # Values frozen all the way down: a record read from a file (a spec, a
  # lock) is shared by everything that reads it, and none of them may change
  # it for the others.
  module Frozen
    module_function

    # +value+ with every Hash, Array and String in it frozen, as copies
    # where they were not (the caller's own are left as they are); other
    # objects are frozen themselves.
    def deep(value)
      case value
      when Hash then value.to_h { |key, item| [deep(key), deep(item)] }.freeze
      when Array then value.map { |item| deep(item) }.freeze
      when String then -value
      else value.freeze
      end
    end
  end
end
