# frozen_string_literal: true

module Relspec
  # Text from a spec, a workspace or an index, made safe to print on one
  # line of a terminal: control characters (a newline would forge a line of
  # relspec's own output, an escape sequence clear the screen or recolour
  # it) and the bidirectional overrides (which reorder what is shown) are
  # written as Ruby's escapes (\n, \e, \u202E); everything else is kept.
  module Printable
    UNSAFE = /[\p{Cc}\u202A-\u202E\u2066-\u2069]/
    SHORT = { "\n" => "\\n", "\t" => "\\t", "\r" => "\\r", "\e" => "\\e" }.freeze

    module_function

    def text(value)
      escaped(utf8(value))
    end

    # Text of several lines (a tool's output, a message with a hint) with
    # its own line breaks and tabs kept (they neither forge a line nor
    # drive the terminal), everything else escaped as +text+ does.
    def lines(value)
      utf8(value).split("\n", -1).map { |line| line.split("\t", -1).map { |part| escaped(part) }.join("\t") }.join("\n")
    end

    # +value+ as valid UTF-8, bytes that are not written as \x escapes.
    def utf8(value)
      string = value.to_s
      string = string.b.force_encoding(Encoding::UTF_8) unless string.encoding == Encoding::UTF_8
      string.scrub { |bytes| bytes.unpack("C*").map { |byte| format("\\x%02X", byte) }.join }
    end

    def escaped(string)
      return string unless UNSAFE.match?(string)

      string.gsub(UNSAFE) { |char| SHORT.fetch(char) { format("\\u%04X", char.ord) } }
    end
    private_class_method :utf8, :escaped
  end
end
