# frozen_string_literal: true

require_relative "rules/release_identity"
require_relative "rules/parents"
require_relative "rules/targets"
require_relative "rules/pins"
require_relative "rules/blacklist"
require_relative "rules/leave_out"
require_relative "rules/repository"
require_relative "rules/settings"
require_relative "rules/externals"
require_relative "rules/early_cutoff"

module Relspec
  module ReleaseSpec
    # The checks a spec file can pass or fail on its own, after its shape is
    # known to be right. Each rule reads only fields that passed the schema.
    module FileRules
      ALL = [
        Rules::ReleaseIdentity, Rules::Parents, Rules::Targets, Rules::Pins, Rules::Blacklist, Rules::LeaveOut,
        Rules::Repository, Rules::Settings, Rules::Externals, Rules::EarlyCutoff
      ].freeze

      def self.call(spec_file)
        ALL.flat_map { |rule| rule.call(spec_file) }
      end
    end
  end
end
