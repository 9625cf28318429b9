# frozen_string_literal: true

module Relspec
  module Apt
    # The C reader of control files (ext/relspec_deb822), compiled by
    # bin/setup into this folder. Without it relspec reads with its pure Ruby
    # code, which gives the same results, about five times slower.
    module NativeReader
      module_function

      def available?
        return @available unless @available.nil?

        @available = begin
          require_relative "relspec_deb822"
          true
        rescue LoadError
          false
        end
      end
    end
  end
end
