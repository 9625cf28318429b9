# frozen_string_literal: true

require_relative "../location"
require_relative "../diagnostic"

module Relspec
  module Yaml
    # The bytes of a YAML file as UTF-8 text, or a diagnostic at the first
    # byte that is not. Psych reports every encoding error at 1:1; a person
    # needs the line and column of the bad byte. UTF-16 with a byte order
    # mark (YAML allows it) is transcoded first.
    module TextEncoding
      BOMS = { "\xFF\xFE".b => Encoding::UTF_16LE, "\xFE\xFF".b => Encoding::UTF_16BE }.freeze

      # [text, nil] or [nil, diagnostic]
      def self.decode(bytes, file:)
        bytes = bytes.b
        encoding = BOMS.find { |bom, _| bytes.start_with?(bom) }&.last
        return utf16(bytes, encoding, file) if encoding

        text = bytes.dup.force_encoding(Encoding::UTF_8)
        return [text, nil] if text.valid_encoding?

        [nil, invalid_at(text, file, "UTF-8")]
      end

      def self.utf16(bytes, encoding, file)
        text = bytes.byteslice(2..).force_encoding(encoding)
        return [text.encode(Encoding::UTF_8), nil] if text.valid_encoding?

        [nil, invalid_at(text, file, encoding.name)]
      end

      def self.invalid_at(text, file, name)
        line = 1
        column = 1
        text.each_char do |char|
          unless char.valid_encoding?
            return Diagnostic.error("encoding", "invalid #{name} (bytes #{char.bytes.map { |b| format('%02X', b) }.join(' ')})",
                                    location: Location.at(file, line, column),
                                    hint: "save the file as UTF-8")
          end
          if char.encode(Encoding::UTF_8) == "\n"
            line += 1
            column = 1
          else
            column += 1
          end
        end
        nil
      end
      private_class_method :utf16, :invalid_at
    end
  end
end
