# frozen_string_literal: true

require_relative "deb822"

module Relspec
  module Apt
    # Reads only some fields of every stanza of a large index (a Packages file
    # has tens of thousands of stanzas of which the planner needs four or five
    # fields). It searches the whole text once per field with String#index
    # (memchr/memmem speed) and remembers where each field occurs next, so the
    # work per stanza is a handful of comparisons and slices. Files with
    # comments or CRLF ends are handed to the full Deb822 parser instead.
    class PackagesScanner
      def initialize(text)
        @text = text
      end

      # Yields one Hash per stanza holding the wanted fields that it has.
      def each(fields, &)
        return enum_for(:each, fields) unless block_given?
        return Native.scan(@text, fields).first.each(&) if NativeReader.available?

        each_in_ruby(fields, &)
      end

      # The same, in Ruby (used when the C reader is not compiled).
      def each_in_ruby(fields, &)
        return enum_for(:each_in_ruby, fields) unless block_given?
        return each_slow(fields, &) if @text.include?("\r") || @text.match?(/^#/)

        needles = fields.map { |field| "\n#{field}: ".b }
        prefixes = fields.map { |field| "#{field}: ".b }
        upcoming = Array.new(fields.size, -1)
        text = @text
        # a line of only spaces or tabs separates stanzas (deb822(5), and
        # the C reader); make it empty so "\n\n" finds every boundary
        text = text.gsub(/^[ \t]+$/, "") if text.match?(/^[ \t]+$/)
        start = 0
        length = text.bytesize
        while start < length
          start += 1 while start < length && text.getbyte(start) == 10
          break if start >= length

          stop = text.index("\n\n", start) || length
          stanza = {}
          fields.each_with_index do |field, index|
            value = value_of(text, index, needles[index], prefixes[index], upcoming, start, stop)
            stanza[field] = value if value
          end
          yield stanza
          start = stop + 2
        end
      end

      private

      def value_of(text, index, needle, prefix, upcoming, start, stop)
        # a stanza's first line has no newline before it
        if text.getbyte(start) == prefix.getbyte(0) && text.byteslice(start, prefix.bytesize) == prefix
          return line_value(text, start + prefix.bytesize, stop)
        end

        position = upcoming[index]
        if position < start
          position = text.index(needle, start) || text.bytesize
          upcoming[index] = position
        end
        return nil if position >= stop

        line_value(text, position + needle.size, stop)
      end

      def line_value(text, from, stop)
        ends = text.index("\n", from) || text.bytesize
        value = text.byteslice(from, ends - from).force_encoding(Encoding::UTF_8)
        # continuation lines (rare in Packages, but legal)
        while ends < stop && [32, 9].include?(text.getbyte(ends + 1))
          following = text.index("\n", ends + 1) || text.bytesize
          value << "\n" << text.byteslice(ends + 1, following - ends - 1)
          ends = following
        end
        value.strip
      end

      def each_slow(fields)
        Deb822.parse_in_ruby(@text).first.each { |stanza| yield stanza.slice(*fields) }
      end
    end
  end
end
