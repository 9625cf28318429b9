# frozen_string_literal: true

require_relative "../../diagnostic"

module Relspec
  module ReleaseSpec
    module Rules
      # `early_cutoff: { enabled: false }` turns the early cutoff off for the
      # release (docs/abi.md): a reviewer reads why in every rebuild the
      # cutoff would have saved, so a reason is required.
      module EarlyCutoff
        def self.call(file)
          setting = file.usable("early_cutoff")
          return [] unless setting.is_a?(Hash) && setting["enabled"] == false && !setting.key?("reason")

          [Diagnostic.error("early-cutoff-reason", "early_cutoff is turned off without a reason",
                            location: file.key_location(["early_cutoff"]),
                            hint: "write early_cutoff: { enabled: false, reason: \"why every dependent is rebuilt\" }")]
        end
      end
    end
  end
end
