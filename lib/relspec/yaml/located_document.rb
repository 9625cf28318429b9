# frozen_string_literal: true

require "psych"
require_relative "../location"
require_relative "../diagnostic"
require_relative "limits"
require_relative "text_encoding"

module Relspec
  module Yaml
    # A YAML file read into plain Ruby data while remembering where every key
    # and value sits, so that any later check can point at file:line:column.
    #
    # Psych's own loaders forget positions and silently keep the last of two
    # duplicate keys; release specs need both, so we walk the node tree.
    class LocatedDocument
      # Scalars that YAML would turn into dates, symbols or other objects stay
      # strings: a spec only ever means text, numbers, booleans or nothing.
      PLAIN_TYPES = [String, Integer, Float, TrueClass, FalseClass, NilClass].freeze
      ALLOWED_TAGS = [nil, "tag:yaml.org,2002:str", "tag:yaml.org,2002:int", "tag:yaml.org,2002:map",
                      "tag:yaml.org,2002:seq", "!"].freeze

      attr_reader :file, :data, :diagnostics

      # Raised inside the walk when a limit is passed; the document then
      # holds that one diagnostic and no data.
      class LimitExceeded < StandardError
        attr_reader :diagnostic

        def initialize(diagnostic)
          @diagnostic = diagnostic
          super(diagnostic.to_s)
        end
      end

      # +file+ is how the file is named in messages (as the user gave it).
      # Only regular files are read (a FIFO would block forever, a link to
      # /dev/zero never end), and never more than Limits::MAX_BYTES.
      def self.load(file)
        text, refusal = read_text(file)
        refusal ? failed(file, refusal) : parse(text, file: file)
      end

      # The file's text as UTF-8 ([text, nil]) or why it cannot be read as
      # text ([nil, diagnostic]), with the same limits as #load: for readers
      # that look at a file before knowing which format it holds.
      def self.read_text(file)
        refusal = refuse_unreadable(file)
        return [nil, refusal] if refusal

        bytes = File.open(file, "rb") { |io| io.read(Limits::MAX_BYTES + 1) } || ""
        return [nil, too_large(file)] if bytes.bytesize > Limits::MAX_BYTES

        TextEncoding.decode(bytes, file: file)
      rescue SystemCallError => e
        [nil, Diagnostic.error("unreadable-file", "cannot read the file: #{e.message.sub(/ @ .*/, '')}",
                               location: Location.file_only(file))]
      end

      def self.refuse_unreadable(file)
        stat = File.stat(file)
        if !stat.file?
          Diagnostic.error("unreadable-file", "not a regular file (#{stat.ftype})", location: Location.file_only(file),
                                                                                    hint: "give a plain YAML file")
        elsif stat.size > Limits::MAX_BYTES
          too_large(file)
        end
      end
      private_class_method :refuse_unreadable

      def self.too_large(file)
        Diagnostic.error("yaml-limit", "the file is larger than #{Limits::MAX_BYTES / (1024 * 1024)} MiB",
                         location: Location.file_only(file), hint: "relspec reads YAML files up to this size")
      end
      private_class_method :too_large

      def self.parse(text, file:)
        return failed(file, too_large(file)) if text.bytesize > Limits::MAX_BYTES

        text, refusal = TextEncoding.decode(text, file: file)
        return failed(file, refusal) if refusal

        stream = Psych.parse_stream(text, filename: file)
        new(file, stream.children).freeze
      rescue Psych::SyntaxError => e
        message = [e.problem, e.context].compact.join(" ").strip
        failed(file, Diagnostic.error("yaml-syntax", "invalid YAML: #{message}",
                                      location: Location.at(file, e.line, e.column),
                                      hint: "check indentation, colons and closing brackets near this point"))
      end

      def self.failed(file, diagnostic)
        document = allocate
        document.send(:initialize_failed, file, diagnostic)
        document.freeze
      end
      private_class_method :failed

      def initialize(file, documents)
        @file = file
        @positions = {}
        @key_positions = {}
        @raw = {}
        @typed_keys = {}
        @anchors = {}
        @anchor_sizes = {}
        @nodes = 0
        @alias_nodes = 0
        @diagnostics = []
        if documents.size > 1
          node = documents[1]
          @diagnostics << Diagnostic.error("yaml-syntax", "the file holds more than one YAML document",
                                           location: at(node), hint: "keep one release per file; remove the extra `---`")
        end
        root = documents.first&.root
        @data = root ? convert(root, [], 1) : nil
        @diagnostics.freeze
      rescue LimitExceeded => e
        @data = nil
        @diagnostics = [e.diagnostic].freeze
      end

      def ok?
        @diagnostics.none?(&:error?)
      end

      # Where the value at +path+ starts; falls back to the nearest enclosing
      # value, so a missing key is reported at the mapping that lacks it.
      def location(path)
        path = path.dup
        loop do
          found = @positions[path]
          return found if found
          return Location.at(file, 1, 1) if path.empty?

          path.pop
        end
      end

      # Where the key of the entry at +path+ is written (the value's location
      # for sequence items, which have no key).
      def key_location(path)
        @key_positions[path] || location(path)
      end

      # The scalar exactly as written (`20.10` stays "20.10", not 20.1).
      def raw(path)
        @raw[path]
      end

      # Whether the key at the end of +path+ was written plain as something
      # YAML reads as other than text (`7:`, `true:`, `~:`): keys are kept as
      # text, so only this says that the writer did not mean text.
      def typed_key?(path)
        @typed_keys.key?(path)
      end

      private

      def initialize_failed(file, diagnostic)
        @file = file
        @positions = {}
        @key_positions = {}
        @raw = {}
        @data = nil
        @diagnostics = [diagnostic].freeze
      end

      def at(node)
        Location.at(file, node.start_line + 1, node.start_column + 1)
      end

      def convert(node, path, depth)
        path = path.freeze
        @positions[path] = at(node)
        check_depth(node, depth)
        check_tag(node)
        nodes_before = @nodes
        @nodes += 1
        value =
          case node
          when Psych::Nodes::Mapping then convert_mapping(node, path, depth)
          when Psych::Nodes::Sequence
            node.children.each_with_index.map { |child, i| convert(child, path + [i], depth + 1) }.freeze
          when Psych::Nodes::Scalar then convert_scalar(node, path)
          when Psych::Nodes::Alias then resolve_alias(node)
          end
        remember_anchor(node, value, @nodes - nodes_before)
        value
      end

      def remember_anchor(node, value, size)
        return unless node.respond_to?(:anchor) && node.anchor

        @anchors[node.anchor] = value
        @anchor_sizes[node.anchor] = size
      end

      def check_depth(node, depth)
        return if depth <= Limits::MAX_DEPTH

        raise LimitExceeded, Diagnostic.error("yaml-limit", "values nested deeper than #{Limits::MAX_DEPTH} levels",
                                              location: at(node), hint: "a release spec nests a few levels; " \
                                                                        "look for unclosed or repeated brackets")
      end

      # An alias stands for a copy of its anchor's whole tree: count those
      # nodes, so that aliases of aliases cannot multiply into millions.
      def count_alias(node)
        @alias_nodes += @anchor_sizes.fetch(node.anchor, 1)
        @nodes += @anchor_sizes.fetch(node.anchor, 1)
        return if @alias_nodes <= Limits::MAX_ALIAS_NODES

        raise LimitExceeded, Diagnostic.error("yaml-limit", "aliases expand to more than #{Limits::MAX_ALIAS_NODES} values",
                                              location: at(node), hint: "write the values out or use fewer nested aliases")
      end

      def convert_mapping(node, path, depth)
        result = {}
        first_seen = {}
        node.children.each_slice(2) do |key_node, value_node|
          key = mapping_key(key_node)
          next unless key

          key_path = (path + [key]).freeze
          if first_seen.key?(key)
            @diagnostics << Diagnostic.error("duplicate-key", "duplicate key \"#{key}\"", location: at(key_node),
                                                                                          hint: "it is already set at line #{first_seen[key]}; keep only one")
            next
          end
          first_seen[key] = key_node.start_line + 1
          @key_positions[key_path] = at(key_node)
          note_typed_key(key_node, key_path)
          result[key] = convert(value_node, key_path, depth + 1)
        end
        result.freeze
      end

      # A plain key that YAML would read as something else than text.
      def note_typed_key(node, path)
        return if node.quoted || node.tag

        @scanner ||= Psych::ScalarScanner.new(Psych::ClassLoader::Restricted.new([], []))
        value = @scanner.tokenize(node.value)
        @typed_keys[path] = value unless value.is_a?(String)
      rescue Psych::DisallowedClass
        nil
      end

      def mapping_key(node)
        return node.value if node.is_a?(Psych::Nodes::Scalar)

        @diagnostics << Diagnostic.error("wrong-type", "a key must be a plain name, not a list or mapping",
                                         location: at(node))
        nil
      end

      def convert_scalar(node, path)
        @raw[path] = node.value
        return node.value.freeze if node.quoted || node.tag == "!" || node.tag == "tag:yaml.org,2002:str"

        @scanner ||= Psych::ScalarScanner.new(Psych::ClassLoader::Restricted.new([], []))
        value = @scanner.tokenize(node.value)
        PLAIN_TYPES.include?(value.class) ? value : node.value.freeze
      rescue Psych::DisallowedClass
        node.value.freeze
      end

      def resolve_alias(node)
        count_alias(node)
        return @anchors[node.anchor] if @anchors.key?(node.anchor)

        @diagnostics << Diagnostic.error("yaml-syntax", "unknown alias *#{node.anchor}", location: at(node))
        nil
      end

      def check_tag(node)
        return unless node.respond_to?(:tag)
        return if ALLOWED_TAGS.include?(node.tag)

        @diagnostics << Diagnostic.error("yaml-tag", "YAML tag #{node.tag} is not allowed in a release spec",
                                         location: at(node), hint: "write plain values; remove the tag")
      end
    end
  end
end
