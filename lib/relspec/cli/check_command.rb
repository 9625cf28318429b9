# frozen_string_literal: true

require_relative "../availability"

module Relspec
  module CLI
    # `relspec check SPEC`: do the OS dependencies of everything the release
    # builds exist on its targets? Prints the report; exits 1 when a
    # dependency is missing or a source could not answer.
    class CheckCommand
      def initialize(path:, format:, target:, source:, timeout:, launchpad_url:, concurrency:, out:)
        @path = path
        @format = format
        @target = target
        @source = source
        @timeout = timeout
        @launchpad_url = launchpad_url
        @concurrency = concurrency
        @out = out
      end

      def call
        report = Availability.run(@path, target: @target, mode: @source, launchpad_url: @launchpad_url, timeout: @timeout,
                                         concurrency: @concurrency)
        @out.write(report.render(@format))
        report.failed? ? 1 : 0
      end
    end
  end
end
