# frozen_string_literal: true

require_relative "../frozen"

module Relspec
  class Catalog
    # The Ruby each target codename runs (its distribution's, 3.1.2 on
    # bookworm), against which a gem's required_ruby_version is checked
    # before the release packages it: a gem that needs a newer Ruby installs
    # but does not load. Codenames whose Ruby is not known are not checked.
    class TargetRubies
      # codename => its Ruby's version ("3.1.2", or "3.1" where only that is known)
      attr_reader :rubies

      # +rubies+: codename => version text, or nil (unknown).
      def initialize(rubies)
        @rubies = Frozen.deep(rubies.compact.sort.to_h)
        freeze
      end

      NONE = new({})

      # The targets of +effective+ (an effective spec) with their distributions' Ruby.
      def self.of(effective)
        distributions = effective.distributions
        new(effective.targets.keys.to_h do |codename|
          distribution = distributions[codename]
          [codename, distribution&.ruby_release || distribution&.ruby]
        end)
      end

      # [[codename, ruby]] of the targets whose Ruby +requirement+ (a
      # Gem::Requirement, nil for none) excludes. A Ruby known only by
      # major.minor (a distribution a spec defines) is taken as its first
      # release (3.1.0), so that nothing is packaged for a Ruby it may not
      # load on.
      def refusing(requirement)
        return [] unless requirement

        @rubies.reject do |_, ruby|
          requirement.satisfied_by?(Gem::Version.new(ruby.count(".") == 1 ? "#{ruby}.0" : ruby))
        end.to_a
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
