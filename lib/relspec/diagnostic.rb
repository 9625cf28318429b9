# frozen_string_literal: true

require_relative "printable"

module Relspec
  # One finding about a user's input: where, which rule, what went wrong and
  # what to do about it. The core returns these as data; only the CLI turns
  # them into text, so every command reports problems the same way.
  Diagnostic = Struct.new(:severity, :rule, :message, :location, :hint, keyword_init: true) do
    def self.error(rule, message, location:, hint: nil)
      new(severity: :error, rule: rule, message: message, location: location, hint: hint).freeze
    end

    def self.warning(rule, message, location:, hint: nil)
      new(severity: :warning, rule: rule, message: message, location: location, hint: hint).freeze
    end

    def error?
      severity == :error
    end

    # Escaped for a terminal: the location's file may come from the command
    # line, and escaped text stays as it is (Printable keeps backslashes).
    def to_s
      text = "#{Printable.text(location)}: #{severity}[#{rule}]: #{Printable.lines(message)}"
      hint ? "#{text}\n  hint: #{Printable.lines(hint)}" : text
    end

    def to_h
      {
        "severity" => severity.to_s, "rule" => rule, "message" => message,
        "file" => location&.file, "line" => location&.line, "column" => location&.column,
        "hint" => hint
      }
    end

    # Reading order: by file, then position, so output never depends on the
    # order in which checks happened to run.
    def sort_key
      [location&.file.to_s, location&.line || 0, location&.column || 0, rule, message]
    end
  end
end
