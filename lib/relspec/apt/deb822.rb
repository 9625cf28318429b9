# frozen_string_literal: true

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

      # One stanza: fields in file order (field names as written) and the
      # line it starts on.
      Stanza = Struct.new(:fields, :line) do
        def [](name)
          fields[name]
        end
      end

      module_function

      # Every stanza with every field. Raises ParseError.
      def parse(text)
        text = text.delete("\r") if text.include?("\r")
        stanzas = []
        fields = nil
        first_line = nil
        last = nil
        text.split("\n", -1).each_with_index do |line, index|
          first = line.getbyte(0)
          if first.nil? || (first <= 32 && line.strip.empty?)
            stanzas << Stanza.new(fields, first_line) if fields
            fields = nil
            last = nil
          elsif first == 35 # "#"
            next
          elsif first == 32 || first == 9
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

            fields[name] = line[colon + 1..].strip
            last = name
          end
        end
        stanzas << Stanza.new(fields, first_line) if fields
        stanzas
      end
    end
  end
end
