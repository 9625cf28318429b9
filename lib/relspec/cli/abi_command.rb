# frozen_string_literal: true

require_relative "../abi"

module Relspec
  module CLI
    # `relspec abi SPEC`: the ABI verdict of every library the release
    # builds (docs/abi.md). Prints the report; with --fail-on, exits 1 when
    # a library's verdict is that one or worse.
    class AbiCommand
      FAIL_ON = %w[changed incompatible].freeze

      def initialize(path:, out:, target:, against:, format:, fail_on:, out_io:)
        @path = path
        @out = out
        @target = target
        @against = against
        @format = format
        @fail_on = fail_on
        @io = out_io
      end

      def call
        report = Abi.run(@path, out: @out, target: @target, against: @against)
        @io.write(report.render(@format))
        @fail_on && report.fails?(@fail_on) ? 1 : 0
      end
    end
  end
end
