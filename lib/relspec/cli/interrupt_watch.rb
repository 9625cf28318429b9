# frozen_string_literal: true

module Relspec
  module CLI
    # Remembers that SIGINT arrived, and raises Interrupt as Ruby's own
    # handler does. An interrupt that lands inside a C extension's
    # initialisation (openssl.so while net/http loads) can be swallowed
    # there and surface later as an unrelated error (a NameError for a
    # constant the half-initialised extension never defined); whatever
    # error follows a received SIGINT is the interrupt.
    class InterruptWatch
      def initialize
        @received = false
      end

      # Installs the handler for the duration of the block.
      def watch
        previous = trap("INT") do
          @received = true
          raise Interrupt
        end
        yield
      ensure
        trap("INT", previous || "DEFAULT")
      end

      def received?
        @received
      end
    end
  end
end
