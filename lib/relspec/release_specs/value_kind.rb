# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # Names the kind of a YAML value the way a spec author thinks of it.
    module ValueKind
      module_function

      def of(value)
        case value
        when nil then "nothing"
        when String then "a string"
        when Integer, Float then "a number (#{value})"
        when true, false then value.to_s
        when Array then "a list"
        when Hash then "a mapping"
        else value.class.name
        end
      end
    end
  end
end
