# frozen_string_literal: true

require "psych"

module Relspec
  module CLI
    # Renders an effective spec as YAML, each top-level value (and each pin)
    # optionally followed by a comment naming where it was written. Comments
    # are aligned so the values stay readable.
    module AnnotatedYaml
      module_function

      def render(effective, origins:)
        lines = []
        effective.to_h.each do |key, value|
          block = dump(key => value)
          origin = effective.origin(key)
          lines << [block.first, origins && origin && key != "pins" ? origin.to_s : nil]
          if key == "pins" && origins
            lines.concat(pin_lines(effective, value))
          else
            lines.concat(block.drop(1).map { |line| [line, nil] })
          end
        end
        format_lines(lines)
      end

      def pin_lines(effective, pins)
        pins.flat_map do |package, pin|
          block = dump(package => pin).map { |line| "  #{line}" }
          [[block.first, effective.pin_origin(package).to_s], *block.drop(1).map { |line| [line, nil] }]
        end
      end

      def dump(hash)
        Psych.dump(hash, line_width: -1).sub(/\A---\s*\n/, "").lines.map(&:chomp)
      end

      def format_lines(lines)
        width = lines.select { |_line, comment| comment }.map { |line, _| line.size }.max.to_i
        lines.map do |line, comment|
          comment ? "#{line.ljust(width)}  # #{comment}\n" : "#{line}\n"
        end.join
      end
    end
  end
end
