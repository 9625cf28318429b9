# frozen_string_literal: true

require_relative "../names"
require_relative "../value_kind"
require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # `parent` is one release name or a list of them in search order.
      module Parents
        def self.call(file)
          return [] unless file.key?("parent")

          parent = file.value(["parent"])
          entries = parent.is_a?(Array) ? parent.each_with_index.map { |name, i| [name, ["parent", i]] } : [[parent, ["parent"]]]
          if parent.is_a?(Array) && parent.empty?
            return [Diagnostic.error("empty-value", "\"parent\" must not be an empty list", location: file.location(["parent"]),
                                                                                            hint: "remove the key for a release without parents")]
          end

          seen = []
          entries.filter_map do |name, path|
            problem = entry_problem(file, name, seen)
            seen << name
            problem && Diagnostic.error(problem[0], problem[1], location: file.location(path), hint: problem[2])
          end
        end

        def self.entry_problem(_file, name, seen)
          if !name.is_a?(String)
            ["wrong-type", "a parent must be a release name, found #{ValueKind.of(name)}", nil]
          elsif !Names.release?(name)
            ["release-name", "invalid parent release name #{name.inspect}", Names::RELEASE_HINT]
          elsif seen.include?(name)
            ["duplicate-parent", "parent #{name.inspect} is listed twice", "list each parent once"]
          end
        end
      end
    end
  end
end
