# frozen_string_literal: true

require_relative "../printable"
require_relative "../report"

module Relspec
  module CLI
    # `relspec report SPEC`: writes the release's status page (or its data
    # as JSON) and says where.
    class ReportCommand
      def initialize(path:, out:, format:, out_io:)
        @path = path
        @out = out
        @format = format
        @io = out_io
      end

      def call
        @io.puts("wrote #{Printable.text(Report.run(@path, out: @out, format: @format))}")
        0
      end
    end
  end
end
