# frozen_string_literal: true

require "json"
require "psych"

module Relspec
  module Yaml
    # Writes plain data (hashes with string keys, arrays, strings, integers,
    # booleans, nil) as block-style YAML, byte for byte the same for the same
    # data. Strings that YAML would read as something else, or that hold
    # special characters, are double-quoted (JSON string syntax is valid YAML).
    #
    # Psych.dump does the same job about ten times slower, which shows on
    # catalogs and locks of thousands of packages.
    module Writer
      PLAIN = %r{\A[A-Za-z0-9_/$][A-Za-z0-9_./+\-@$,:]*\z}
      SCANNER = Psych::ScalarScanner.new(Psych::ClassLoader::Restricted.new([], []))

      def self.dump(data)
        Emitter.new.dump(data)
      end

      # One document's worth of writing; remembers which strings can stay
      # plain (catalogs and locks repeat branch names, codenames, …).
      class Emitter
        def initialize
          @plain = {}
        end

        def dump(data)
          out = +"---"
          if (data.is_a?(Hash) || data.is_a?(Array)) && !data.empty?
            out << "\n"
            emit(data, 0, out)
          else
            out << " " << scalar_or_empty(data) << "\n"
          end
          out
        end

        # Mapping keys and sequence dashes of +value+ start at column +indent+.
        def emit(value, indent, out)
          if value.is_a?(Hash)
            value.each { |key, item| entry(out, indent, "#{scalar(key.to_s)}:", item, value_indent: indent + 2, list_indent: indent) }
          else
            value.each { |item| entry(out, indent, "-", item, value_indent: indent + 2, list_indent: indent + 2) }
          end
        end

        def entry(out, indent, head, item, value_indent:, list_indent:)
          out << (" " * indent) << head
          if item.is_a?(Hash) && !item.empty?
            out << "\n"
            emit(item, value_indent, out)
          elsif item.is_a?(Array) && !item.empty?
            out << "\n"
            emit(item, list_indent, out)
          else
            out << " " << scalar_or_empty(item) << "\n"
          end
        end

        def scalar_or_empty(value)
          return "{}" if value.is_a?(Hash)
          return "[]" if value.is_a?(Array)

          scalar(value)
        end

        def scalar(value)
          case value
          when String then plain_memo(value) ? value : JSON.generate(value)
          when Integer, true, false then value.to_s
          when nil then "null"
          else raise ArgumentError, "cannot write #{value.class} as YAML"
          end
        end

        def plain_memo(text)
          @plain.fetch(text) { @plain[text] = plain?(text) }
        end

        def plain?(text)
          return false unless PLAIN.match?(text) && !text.end_with?(":")

          SCANNER.tokenize(text) == text
        rescue Psych::DisallowedClass
          false
        end
      end
    end
  end
end
