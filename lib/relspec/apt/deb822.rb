# frozen_string_literal: true

require_relative "native"

module Relspec
  module Apt
    # Control-file syntax (deb822(5)): stanzas of "Field: value" lines
    # separated by blank lines, continuation lines start with a space or a
    # tab, lines starting with # are comments. CRLF line ends are accepted.
    module Deb822
      # Malformed input; +line+ is 1-based.
      class ParseError < StandardError
        attr_reader :line

        def initialize(message, line)
          super("line #{line}: #{message}")
          @line = line
        end
      end

      module_function

      # Every stanza as a Hash of its fields in file order (names as written,
      # values in UTF-8). Raises ParseError.
      def parse(text)
        parse_with_lines(text).first
      end

      # Yields each stanza's fields and the line it starts on, without
      # keeping them (for reading large indices once).
      def each(text, &block)
        return enum_for(:each, text) unless block

        if NativeReader.available?
          Native.parse(text, &block)
        else
          stanzas, lines = parse_in_ruby(text)
          stanzas.each_with_index { |fields, index| yield fields, lines[index] }
        end
      end

      # [stanzas, lines]: the stanzas and the line each one starts on.
      def parse_with_lines(text)
        NativeReader.available? ? Native.parse(text) : parse_in_ruby(text)
      end

      # The same as parse_with_lines, in Ruby (used when the C reader is not
      # compiled).
      def parse_in_ruby(text)
        text = text.dup.force_encoding(Encoding::UTF_8)
        text = text.delete("\r") if text.include?("\r")
        stanzas = []
        lines = []
        fields = nil
        first_line = nil
        last = nil
        text.split("\n", -1).each_with_index do |line, index|
          first = line.getbyte(0)
          if first.nil? || (first <= 32 && line.strip.empty?)
            if fields
              stanzas << fields
              lines << first_line
            end
            fields = nil
            last = nil
          elsif first == 35 # "#"
            next
          elsif [32, 9].include?(first)
            raise ParseError.new("continuation line outside of a field", index + 1) unless last

            fields[last] = "#{fields[last]}\n#{line}"
          else
            colon = line.index(":")
            space = line.index(" ")
            if colon.nil? || colon.zero? || (space && space < colon)
              raise ParseError.new("expected \"Field: value\", found #{line[0, 60].inspect}", index + 1)
            end

            unless fields
              fields = {}
              first_line = index + 1
            end
            name = line[0, colon]
            raise ParseError.new("field #{name} appears twice in one stanza", index + 1) if fields.key?(name)

            fields[name] = line[(colon + 1)..].strip
            last = name
          end
        end
        if fields
          stanzas << fields
          lines << first_line
        end
        [stanzas, lines]
      end
    end
  end
end
