# frozen_string_literal: true

require_relative "../error"

module Relspec
  module CLI
    # Numeric options whose values Thor accepts but relspec cannot use
    # (`--jobs -3`, `--timeout -5`, `--timeout 0`): refused before any work
    # starts. Included in every Thor class that declares such options.
    module CheckedOptions
      # option name → [what it must be, test]
      RULES = {
        "jobs" => ["a whole number of 1 or more", ->(v) { v.is_a?(Integer) && v >= 1 }],
        "concurrency" => ["a whole number of 1 or more", ->(v) { v.is_a?(Integer) && v >= 1 }],
        "timeout" => ["a number of seconds above 0", ->(v) { v.is_a?(Numeric) && v.positive? && v.finite? }]
      }.freeze

      def self.check!(options)
        RULES.each do |name, (wanted, test)|
          next unless options.key?(name)

          value = options[name]
          raise InvalidOption, "--#{name} must be #{wanted}, not #{value}" unless test.call(value)
        end
      end

      def invoke_command(command, *args)
        CheckedOptions.check!(options)
        super
      end
    end
  end
end
