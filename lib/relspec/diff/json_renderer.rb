# frozen_string_literal: true

require "json"

module Relspec
  module Diff
    # The diff for tools: the versioned document described in docs/diff.md.
    module JsonRenderer
      FORMAT_KEY = "relspec_diff"
      FORMAT_VERSION = 1

      module_function

      # +abi+: release => Abi::Report, under "abi" when there is one.
      def render(diffs, abi: {})
        document = { FORMAT_KEY => FORMAT_VERSION, "changed" => diffs.any?(&:changed?),
                     "rebuilds" => diffs.sum(&:rebuilds), "releases" => diffs.map(&:to_h) }
        document["abi"] = abi.transform_values { |report| report.to_h["targets"] } unless abi.empty?
        "#{JSON.pretty_generate(document)}\n"
      end
    end
  end
end
