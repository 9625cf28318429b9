# frozen_string_literal: true

require "rexml/parsers/pullparser"
require_relative "../error"
require_relative "verdict"

module Relspec
  module Abi
    # An oroGen typekit's type registry (typelib's .tlb XML, installed as
    # share/orogen/<typekit>.tlb): the types components exchange over the
    # wire, each with its size and, for compounds, its fields' names, types
    # and offsets. Two registries compare type by type: removed types make
    # the typekit incompatible, a type whose layout (size, fields, offsets,
    # field types) moved makes it changed, added types only compatible
    # (docs/abi.md).
    #
    # A registry comes from a repository (an ancestor's published dumps), so
    # it is untrusted: it is read as a stream of events, never as a tree, a
    # DTD (the place entity definitions live: a "billion laughs" expands a
    # few hundred bytes into gigabytes) is refused at its first byte, and
    # its size and its number of types are bounded (docs/limits.md), so
    # that no registry costs more than a few seconds and a few hundred MB.
    class TypeRegistry
      # +fields+: [name, type, offset] in the registry's order.
      Type = Struct.new(:name, :kind, :size, :fields, keyword_init: true)

      KINDS = %w[compound opaque numeric enum container array pointer null alias].freeze
      # Rock's base typekit is 0.2 MB with 188 types: forty times that is
      # still read in about 4 s; the count bounds registries of small types.
      MAX_BYTES = 8 * 1024 * 1024
      MAX_TYPES = 50_000
      # The XML's own entities, and character references: what typelib
      # writes in a name (std::vector&lt;double&gt;). Any other is defined by
      # a DTD, which a registry does not have.
      ENTITIES = { "lt" => "<", "gt" => ">", "amp" => "&", "quot" => '"', "apos" => "'" }.freeze
      REFERENCE = /&(?:#(\d+)|#x(\h+)|([^;&\s]*));/
      DECLARATIONS = %i[start_doctype entitydecl elementdecl attlistdecl notationdecl externalentity].freeze

      attr_reader :types

      # The registry in the file +path+, its size checked before it is read.
      def self.read(path, file:)
        too_large(file, File.size(path)) if File.size(path) > MAX_BYTES
        parse(File.read(path), file: file)
      end

      # The registry of the .tlb text +xml+ (+file+ names it in errors).
      def self.parse(xml, file:)
        too_large(file, xml.bytesize) if xml.bytesize > MAX_BYTES
        new(Reading.new(file).call(REXML::Parsers::PullParser.new(xml)))
      rescue REXML::ParseException => e
        raise ToolError, "#{file} is not a typelib registry: #{e.message.lines.first&.strip}"
      end

      def self.too_large(file, bytes)
        raise ToolError, "#{file} is a type registry of #{bytes} bytes, more than #{MAX_BYTES}: not compared"
      end
      private_class_method :too_large

      # One pass over a registry's events: the types of its <typelib> root.
      class Reading
        def initialize(file)
          @file = file
          @types = []
          @depth = 0
        end

        def call(parser)
          while parser.has_next?
            event = parser.pull
            refuse_declaration if DECLARATIONS.include?(event.event_type)
            case event.event_type
            when :start_element then start(event[0], event[1])
            when :end_element then finish
            end
          end
          raise ToolError, "#{@file} is not a typelib registry (no <typelib> root)" unless @root

          @types
        end

        private

        def start(name, attributes)
          @depth += 1
          if @depth == 1
            raise ToolError, "#{@file} is not a typelib registry (no <typelib> root)" unless name == "typelib"

            @root = true
          elsif @depth == 2 && KINDS.include?(name)
            too_many if @types.size >= MAX_TYPES
            @type = { name: text(attributes["name"]), kind: name, size: attributes["size"] && text(attributes["size"]).to_i,
                      fields: [] }
          elsif @depth == 3 && @type && name == "field"
            @type[:fields] << [text(attributes["name"]), text(attributes["type"]),
                               attributes["offset"] && text(attributes["offset"]).to_i]
          end
        end

        def finish
          if @depth == 2 && @type
            @types << Type.new(**@type, fields: @type[:fields].freeze).freeze
            @type = nil
          end
          @depth -= 1
        end

        # An attribute's value as written (PullParser hands it on raw),
        # its references resolved.
        def text(raw)
          return nil if raw.nil?

          raw.gsub(REFERENCE) do
            decimal, hexadecimal, name = Regexp.last_match.captures
            code = decimal ? decimal.to_i : hexadecimal&.to_i(16)
            next [code].pack("U") if code && code <= 0x10FFFF

            ENTITIES.fetch(name) { refuse_reference(Regexp.last_match[0]) }
          end
        end

        def refuse_declaration
          raise ToolError, "#{@file} has a DTD (<!DOCTYPE>: entity definitions), which a typelib registry never has: " \
                           "refused, not compared"
        end

        def refuse_reference(reference)
          raise ToolError, "#{@file} refers to the entity #{reference[0, 40].inspect}, which no typelib registry " \
                           "defines: refused, not compared"
        end

        def too_many
          raise ToolError, "#{@file} is a type registry of more than #{MAX_TYPES} types: not compared (the rest was " \
                           "not read)"
        end
      end
      private_constant :Reading

      def initialize(types)
        @types = types.to_h { |type| [type.name, type] }.freeze
        freeze
      end

      # The Verdict of +new+ against this registry: the summary counts and
      # the changes, type by type, sorted by name.
      def compare(new)
        removed = (types.keys - new.types.keys).sort
        added = (new.types.keys - types.keys).sort
        changed = (types.keys & new.types.keys).sort.filter_map do |name|
          lines = layout_changes(types[name], new.types[name])
          [name, lines] unless lines.empty?
        end
        verdict = if removed.any? then "incompatible"
                  elsif changed.any? then "changed"
                  elsif added.any? then "compatible"
                  else "unchanged"
                  end
        summary = ["Types changes summary: #{removed.size} Removed, #{changed.size} Changed, #{added.size} Added types"]
        changes = removed.map { |name| "[D] #{name}" } + changed.flat_map { |name, lines| ["[C] #{name}:", *lines] } +
                  added.map { |name| "[A] #{name}" }
        Verdict.new(verdict: verdict, summary: summary.freeze, changes: changes.first(Verdict::CHANGE_LINES).freeze).freeze
      end

      private

      def layout_changes(old, new)
        lines = []
        lines << "  kind #{old.kind} -> #{new.kind}" if old.kind != new.kind
        lines << "  size #{old.size} -> #{new.size} bytes" if old.size != new.size
        old_fields = old.fields.to_h { |name, type, offset| [name, [type, offset]] }
        new_fields = new.fields.to_h { |name, type, offset| [name, [type, offset]] }
        old.fields.each do |name, type, offset|
          next lines << "  field #{name} (#{type}) removed" unless new_fields.key?(name)

          new_type, new_offset = new_fields[name]
          lines << "  field #{name} type #{type} -> #{new_type}" if new_type != type
          lines << "  field #{name} offset #{offset} -> #{new_offset}" if new_offset != offset
        end
        new.fields.each do |name, type, offset|
          lines << "  field #{name} (#{type}) added at offset #{offset}" unless old_fields.key?(name)
        end
        lines
      end
    end
  end
end
