# frozen_string_literal: true

require_relative "hierarchy"
require_relative "inheritance"
require_relative "hierarchy_rules"
require_relative "lineage"

module Relspec
  module ReleaseSpec
    # Everything relspec knows about one release spec after reading it and
    # its ancestors: the hierarchy, the effective spec, and every diagnostic
    # of every file involved.
    class Resolution
      attr_reader :spec_file, :hierarchy, :effective, :diagnostics

      def self.of(library, path)
        new(library, library.load(path))
      end

      def initialize(library, spec_file)
        @spec_file = spec_file
        @hierarchy = Hierarchy.build(library, spec_file)
        @effective, broken = Inheritance.call(@hierarchy)
        found = @hierarchy.spec_files.flat_map(&:diagnostics) + @hierarchy.diagnostics
        if spec_file.data.is_a?(Hash)
          complete = @hierarchy.diagnostics.empty? && @hierarchy.spec_files.all?(&:ok?)
          found += HierarchyRules.call(@effective, broken, spec_file, lineage_complete: complete)
        end
        @diagnostics = found.uniq(&:to_s).sort_by(&:sort_key).freeze
        freeze
      end

      # The release's repositories, its own first, then its ancestors' in
      # search order (Lineage).
      def lineage
        Lineage.of(self)
      end

      def ok?
        diagnostics.none?(&:error?)
      end

      def errors
        diagnostics.select(&:error?)
      end

      def warnings
        diagnostics.reject(&:error?)
      end
    end
  end
end
