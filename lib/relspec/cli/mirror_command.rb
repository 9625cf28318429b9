# frozen_string_literal: true

require_relative "../mirror"

module Relspec
  module CLI
    # `relspec mirror SPEC --out DIR` makes or updates a field mirror of a
    # release; `relspec mirror verify DIR` checks one again, offline. Prints
    # the report; exits 1 when the mirror is not proven complete.
    class MirrorCommand
      # +options+: Thor's (out, target, format, install, timeout, quiet).
      def initialize(args:, options:, out_io:, err_io:)
        @args = args
        @out = options[:out]
        @targets = options[:target] || []
        @format = options[:format]
        @install = options[:install]
        @timeout = options[:timeout]
        @io = out_io
        @err = err_io
        @progress = options[:quiet] ? nil : err_io
      end

      def call
        report = if @args.first == "verify"
                   Mirror.verify(directory, install: @install)
                 else
                   Mirror.run(spec, out: output, targets: @targets, timeout: @timeout, progress: @progress,
                                    install: @install, notes: @err)
                 end
        @io.write(report.render(@format))
        report.complete? ? 0 : 1
      end

      private

      def directory
        return @args[1] if @args.size == 2

        raise InvalidOption, "relspec mirror verify takes one folder: relspec mirror verify DIR"
      end

      def spec
        return @args.first if @args.size == 1

        raise InvalidOption, "relspec mirror takes one spec: relspec mirror SPEC --out DIR (or: relspec mirror verify DIR)"
      end

      def output
        return @out if @out && !@out.empty?

        raise InvalidOption, "relspec mirror SPEC needs --out DIR: the folder the mirror is made in"
      end
    end
  end
end
