# frozen_string_literal: true

require "rexml/document"
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
    class TypeRegistry
      # +fields+: [name, type, offset] in the registry's order.
      Type = Struct.new(:name, :kind, :size, :fields, keyword_init: true)

      KINDS = %w[compound opaque numeric enum container array pointer null alias].freeze

      attr_reader :types

      # The registry of the .tlb text +xml+ (+file+ names it in errors).
      def self.parse(xml, file:)
        document = REXML::Document.new(xml)
        root = document.root
        raise ToolError, "#{file} is not a typelib registry (no <typelib> root)" unless root&.name == "typelib"

        new(root.elements.filter_map { |element| type(element) if KINDS.include?(element.name) })
      rescue REXML::ParseException => e
        raise ToolError, "#{file} is not a typelib registry: #{e.message.lines.first&.strip}"
      end

      def self.type(element)
        fields = element.get_elements("field").map do |field|
          [field.attributes["name"], field.attributes["type"], field.attributes["offset"]&.to_i]
        end
        size = element.attributes["size"]
        Type.new(name: element.attributes["name"], kind: element.name, size: size&.to_i, fields: fields.freeze).freeze
      end
      private_class_method :type

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
