# frozen_string_literal: true

require_relative "external_release"
require_relative "../diagnostic"
require_relative "../suggestion"

module Relspec
  module ReleaseSpec
    # The release graph above one spec: every parent resolved to a spec file
    # of the library or to an external release, with cycles cut and reported.
    class Hierarchy
      # One release in the graph; +source+ is a SpecFile or an ExternalRelease.
      Node = Struct.new(:name, :source, :parents, keyword_init: true) do
        def external?
          source.is_a?(ExternalRelease)
        end
      end

      attr_reader :root, :diagnostics, :library

      def self.build(library, spec_file)
        new(library, spec_file)
      end

      def initialize(library, spec_file)
        @library = library
        @nodes = {}
        @diagnostics = []
        @root = visit(spec_file.release || spec_file.file_release, spec_file, [])
        @diagnostics.freeze
        freeze
      end

      # Ancestors in search order: depth first, parents in the order written,
      # each release once. A release's own lineage is searched before the
      # next parent's, because it already holds what its ancestors hold.
      def ancestors
        order = []
        seen = { root.name => true }
        walk = lambda do |node|
          node.parents.each do |parent|
            next if seen[parent.name] # a release is identified by its name

            seen[parent.name] = true
            order << parent
            walk.call(parent)
          end
        end
        walk.call(root)
        order
      end

      # Every spec file of the graph (the root included).
      def spec_files
        [root, *ancestors].reject(&:external?).map(&:source)
      end

      private

      def visit(name, spec_file, chain)
        return @nodes[name] if @nodes.key?(name)

        node = Node.new(name: name, source: spec_file, parents: [])
        @nodes[name] = node
        chain += [name]
        spec_file.parents.each do |parent_name|
          parent = resolve(spec_file, parent_name, chain)
          node.parents << parent if parent
        end
        node.parents.freeze
        node.freeze
      end

      def resolve(spec_file, name, chain)
        if chain.include?(name)
          cycle = chain[chain.index(name)..] + [name]
          report(spec_file, name, "parent-cycle", "parent cycle: #{cycle.join(' -> ')}",
                 "a release cannot inherit from itself; remove one of these parents")
          return nil
        end

        found = @library.find(name)
        external = externals(spec_file)[name]
        if found && external
          report(spec_file, name, "ambiguous-parent",
                 "parent #{name.inspect} is both #{found.path} and an external release",
                 "remove the external entry or the spec file")
          return nil
        end
        return external_node(spec_file, name, external) if external
        return visit(name, found, chain) if found

        unknown_parent(spec_file, name)
        nil
      end

      # One node per external release name, however many specs declare it;
      # declarations that disagree are an error.
      def external_node(spec_file, name, external)
        known = @nodes[name]
        if known && !(known.external? && known.source.same_entry?(external))
          where = known.external? ? known.source.declared_in.path : "specs/"
          report(spec_file, name, "conflicting-external",
                 "external release #{name.inspect} is declared differently here and in #{where}",
                 "declare it the same way in both specs (or in one common ancestor)")
          return nil
        end
        @nodes[name] ||= Node.new(name: name, source: external, parents: [].freeze).freeze
      end

      def externals(spec_file)
        entries = spec_file.usable("external")
        return {} unless entries.is_a?(Hash)

        entries.select { |_name, entry| entry.is_a?(Hash) }
               .to_h { |name, entry| [name, ExternalRelease.new(name, entry, spec_file)] }
      end

      def unknown_parent(spec_file, name)
        candidates = @library.names + externals(spec_file).keys
        hint = Suggestion.hint(name, candidates) ||
               "add #{@library.path_for(name)} or declare it under `external:` with its repository url"
        report(spec_file, name, "unknown-parent",
               "unknown parent #{name.inspect}: no #{@library.path_for(name)} and no external release of that name", hint)
      end

      def report(spec_file, name, rule, message, hint)
        parent = spec_file.value(["parent"])
        path = parent.is_a?(Array) ? ["parent", parent.index(name)] : ["parent"]
        @diagnostics << Diagnostic.error(rule, message, location: spec_file.location(path), hint: hint)
      end
    end
  end
end
