# frozen_string_literal: true

module Relspec
  # The little relspec reads of an ELF file's bytes: its sections, its GNU
  # build id, and its bytes without what only debuggers read. The bytes come
  # from a build, so every offset is checked against their size and a
  # malformed file reads as one without sections.
  module ElfFile
    MAGIC = "\x7FELF".b
    SHT_NOTE = 7
    NOTE_GNU_BUILD_ID = 3
    # A build id is 8 to 64 bytes (ld's sha1 gives 20).
    BUILD_ID = /\A[0-9a-f]{16,128}\z/
    # Sections that name the build's debug files (their build id, CRC and
    # dwz multifile): they move when the debug information does (a line
    # number, a build path) although not one instruction or datum did.
    DEBUG_LINKS = %w[.gnu_debuglink .gnu_debugaltlink .note.gnu.build-id].freeze

    Section = Struct.new(:name, :type, :offset, :size, keyword_init: true)

    module_function

    def elf?(bytes)
      bytes.start_with?(MAGIC) && bytes.bytesize >= 64
    end

    # The sections of +bytes+ whose data lie within them, with their names.
    def sections(bytes)
      return [] unless elf?(bytes)

      format = Format.new(bytes)
      raw = format.headers
      names = raw[format.names_index]
      raw.filter_map do |type, offset, size, name_at|
        next unless type

        Section.new(name: names ? string(bytes, names[1] + name_at, names[1] + names[2]) : "", type: type,
                    offset: offset, size: size).freeze
      end
    end

    # The GNU build id of +bytes+ (hex), nil when there is none.
    def build_id(bytes)
      sections(bytes).each do |section|
        next unless section.type == SHT_NOTE

        id = note_id(bytes, section.offset, section.size, Format.new(bytes).long)
        return id if id
      end
      nil
    end

    # +bytes+ with the data of DEBUG_LINKS zeroed (the layout kept): two
    # builds of the same code compare equal however their debug files differ.
    def without_debug_links(bytes)
      copy = bytes.b
      sections(bytes).each do |section|
        copy[section.offset, section.size] = "\0" * section.size if DEBUG_LINKS.include?(section.name)
      end
      copy
    end

    def string(bytes, from, limit)
      return "" if from >= limit || from >= bytes.bytesize

      ending = bytes.index("\0", from)
      ending && ending < limit ? bytes.byteslice(from, ending - from) : ""
    end

    # Walks the notes of one section for NT_GNU_BUILD_ID owned by "GNU".
    def note_id(bytes, offset, size, long)
      at = offset
      while at + 12 <= offset + size
        name_size, desc_size, type = bytes.unpack("#{long}3", offset: at)
        desc_at = at + 12 + align(name_size)
        return nil if desc_at + desc_size > offset + size

        if type == NOTE_GNU_BUILD_ID && bytes.byteslice(at + 12, name_size) == "GNU\0"
          id = bytes.byteslice(desc_at, desc_size).unpack1("H*")
          return id if id.match?(BUILD_ID)
        end
        at = desc_at + align(desc_size)
      end
      nil
    end

    def align(size)
      (size + 3) & ~3
    end

    # The header fields of one ELF class and byte order.
    class Format
      attr_reader :long

      def initialize(bytes)
        @bytes = bytes
        @wide = bytes.getbyte(4) == 2
        big = bytes.getbyte(5) == 2
        @short = big ? "n" : "v"
        @long = big ? "N" : "V"
        @quad = big ? "Q>" : "Q<"
      end

      def names_index
        @bytes.unpack1(@short, offset: @wide ? 0x3e : 0x32)
      end

      # [type, offset, size, name offset] of each section by index; [] for
      # a section whose data lie outside the bytes; none when the table does.
      def headers
        table, entry, count = header_table
        return [] if table + (entry * count) > @bytes.bytesize

        (0...count).map do |index|
          at = table + (index * entry)
          name_at, type = @bytes.unpack("#{@long}2", offset: at)
          offset, size = @wide ? @bytes.unpack("#{@quad}2", offset: at + 24) : @bytes.unpack("#{@long}2", offset: at + 16)
          offset + size <= @bytes.bytesize ? [type, offset, size, name_at] : []
        end
      end

      def header_table
        if @wide
          [@bytes.unpack1(@quad, offset: 0x28), 64, @bytes.unpack1(@short, offset: 0x3c)]
        else
          [@bytes.unpack1(@long, offset: 0x20), 40, @bytes.unpack1(@short, offset: 0x30)]
        end
      end
    end
  end
end
