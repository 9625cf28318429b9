# frozen_string_literal: true

module Relspec
  module ReleaseSpec
    # The spec's `early_cutoff` (docs/spec-reference.md): +enabled+ unless
    # the release turns it off, with its +reason+ (docs/abi.md).
    EarlyCutoff = Struct.new(:enabled, :reason, keyword_init: true) do
      # The setting of the mapping as written (nil: on).
      def self.from(mapping)
        return new(enabled: true, reason: nil).freeze if mapping.nil?

        new(enabled: mapping["enabled"] != false, reason: mapping["reason"]).freeze
      end
    end
  end
end
