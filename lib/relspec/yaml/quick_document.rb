# frozen_string_literal: true

require "psych"
require_relative "limits"
require_relative "located_document"
require_relative "text_encoding"

module Relspec
  module Yaml
    # The same data as LocatedDocument, read about twice as fast because no
    # position is kept: Psych's events build the values directly, without a
    # node tree. For files relspec writes itself and reads often (a lock of
    # 400 packages: ~45 ms instead of ~95 ms), whose reader re-reads the file
    # with LocatedDocument only when it has an error to place at file:line.
    #
    # Whatever LocatedDocument would report or treat specially — a syntax or
    # encoding error, a limit passed, a duplicate or non-scalar key, a tag, an
    # anchor or alias, a second document — makes +parse+ return nil, and the
    # caller reads the file with LocatedDocument instead, so the data given
    # here is always the data LocatedDocument would give.
    class QuickDocument
      attr_reader :data

      # The document, or nil when it must be read with LocatedDocument.
      def self.parse(text)
        return nil if text.bytesize > Limits::MAX_BYTES

        text, refusal = TextEncoding.decode(text, file: nil)
        return nil if refusal

        builder = Builder.new
        Psych::Parser.new(builder).parse(text)
        new(builder.root, builder.raw)
      rescue Psych::SyntaxError, Builder::Unsuitable
        nil
      end

      def initialize(data, raw)
        @data = data
        @raw = raw
      end

      def ok?
        true
      end

      def diagnostics
        []
      end

      # The scalar exactly as written, as LocatedDocument#raw, for scalars
      # that are not text (`20.10` stays "20.10"); a text value is its own
      # raw form.
      def raw(path)
        @raw[path]
      end

      # Never: a plain key that is not text makes #parse give nil, and
      # LocatedDocument#typed_key? says where.
      def typed_key?(_path)
        false
      end

      # Positions are not kept: readers re-read with LocatedDocument to say
      # where an error is.
      def location(_path)
        nil
      end

      def key_location(_path)
        nil
      end

      # Psych events into plain values, as LocatedDocument converts nodes.
      class Builder < Psych::Handler
        # Something LocatedDocument would diagnose or treat specially.
        class Unsuitable < StandardError; end

        attr_reader :root, :raw

        def initialize
          super
          @stack = [] # open containers: [Hash, path, pending key] or [Array, path]
          @raw = {}
          @documents = 0
        end

        def start_document(_version, _tag_directives, _implicit)
          @documents += 1
          raise Unsuitable if @documents > 1
        end

        def start_mapping(anchor, tag, _implicit, _style)
          open({}, anchor, tag)
        end

        def start_sequence(anchor, tag, _implicit, _style)
          open([], anchor, tag)
        end

        def end_mapping
          raise Unsuitable if @stack.last[2] # a key without value

          close
        end

        def end_sequence
          close
        end

        def scalar(value, anchor, tag, _plain, quoted, _style)
          raise Unsuitable if anchor || tag

          top = @stack.last
          if top && top[0].is_a?(Hash) && top[2].nil?
            raise Unsuitable if top[0].key?(value) # duplicate key
            raise Unsuitable unless quoted || convert_key(value).is_a?(String) # LocatedDocument#typed_key?

            top[2] = value
          else
            add(convert(value, quoted))
          end
        end

        def alias(_anchor)
          raise Unsuitable
        end

        private

        def open(container, anchor, tag)
          raise Unsuitable if anchor || tag

          top = @stack.last
          raise Unsuitable if top && top[0].is_a?(Hash) && top[2].nil? # a mapping or list as key
          raise Unsuitable if @stack.size >= Limits::MAX_DEPTH - 1 # LocatedDocument says where

          @stack.push([container, top ? path_of(top) : []])
        end

        def close
          container, = @stack.pop
          add(container)
        end

        # The value goes into the open container (or becomes the root).
        def add(value)
          top = @stack.last
          return @root = value unless top

          if top[0].is_a?(Hash)
            top[0][top[2]] = value
            top[2] = nil
          else
            top[0] << value
          end
        end

        # The path of the next value of +top+: its pending key or next index.
        def path_of(top)
          top[1] + [top[0].is_a?(Hash) ? top[2] : top[0].size]
        end

        # Keys are mostly names ("base/types", "decision"): a key starting
        # with a letter is text unless it is one of YAML's words.
        WORDS = /\A(?:yes|true|on|no|false|off|null)\z/i

        def convert_key(value)
          return value if value.match?(/\A[A-Za-z]/) && !value.match?(WORDS)

          @scanner ||= Psych::ScalarScanner.new(Psych::ClassLoader::Restricted.new([], []))
          @scanner.tokenize(value)
        rescue Psych::DisallowedClass
          value
        end

        def convert(value, quoted)
          return value if quoted

          @scanner ||= Psych::ScalarScanner.new(Psych::ClassLoader::Restricted.new([], []))
          converted = @scanner.tokenize(value)
          return value unless LocatedDocument::PLAIN_TYPES.include?(converted.class)
          return converted if converted.is_a?(String)

          top = @stack.last
          @raw[top ? path_of(top) : []] = value
          converted
        rescue Psych::DisallowedClass
          value
        end
      end
    end
  end
end
