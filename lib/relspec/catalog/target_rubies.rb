# frozen_string_literal: true

require_relative "../frozen"

module Relspec
  class Catalog
    # The Ruby each target codename runs (its distribution's, "3.1" on
    # bookworm), against which a gem's required_ruby_version is checked
    # before the release packages it: a gem that needs a newer Ruby installs
    # but does not load. Codenames whose Ruby is not known are not checked.
    class TargetRubies
      # codename => "major.minor"
      attr_reader :rubies

      # +rubies+: codename => "major.minor" or nil (unknown).
      def initialize(rubies)
        @rubies = Frozen.deep(rubies.compact.sort.to_h)
        freeze
      end

      NONE = new({})

      # The targets of +effective+ (an effective spec) with their distributions' Ruby.
      def self.of(effective)
        distributions = effective.distributions
        new(effective.targets.keys.to_h { |codename| [codename, distributions[codename]&.ruby] })
      end

      # [[codename, ruby]] of the targets whose Ruby +requirement+ (a
      # Gem::Requirement, nil for none) excludes. A distribution names its
      # Ruby by major.minor: it is taken as its first release (3.1.0), so
      # that nothing is packaged for a Ruby it may not load on.
      def refusing(requirement)
        return [] unless requirement

        @rubies.reject { |_, ruby| requirement.satisfied_by?(Gem::Version.new("#{ruby}.0")) }.to_a
      end

      # These Rubies but those of +codenames+.
      def without(codenames)
        TargetRubies.new(@rubies.except(*codenames))
      end

      # "Ruby 3.1 (bookworm)" for what #refusing returns.
      def self.describe(refused)
        refused.map { |codename, ruby| "Ruby #{ruby} (#{codename})" }.join(", ")
      end
    end
  end
end
