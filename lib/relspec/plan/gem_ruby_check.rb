# frozen_string_literal: true

require_relative "gem_check"
require_relative "../catalog/target_rubies"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  module Plan
    # No target builds a gem its Ruby cannot load. Gem resolution picks
    # versions every target's Ruby runs, except where it relies on a
    # target's distribution for the gem (no version runs on its Ruby, and
    # ruby-<gem> there fits): should the planner still build it there (the
    # distribution's package depends on a gem the release gives itself
    # there), the plan stops here instead of shipping a gem that installs
    # but does not load.
    module GemRubyCheck
      module_function

      # +plan+: the ReleasePlan; +release_catalog+: its gems (name =>
      # GemArchive); +resolution+: the spec's. Raises InvalidInput.
      def call(plan, release_catalog, resolution)
        rubies = Catalog::TargetRubies.of(resolution.effective)
        problems = plan.targets.sort_by { |target, _| target.to_s }.flat_map do |target, decisions|
          decisions.sort.filter_map do |name, decision|
            archive = release_catalog.gems[name]
            next unless archive && (decision.build? || decision.published?)

            refused = rubies.refusing(archive.required_ruby).to_h
            next unless refused.key?(target.codename)

            problem(archive, target, refused.fetch(target.codename), decision, resolution)
          end
        end
        raise InvalidInput, problems unless problems.empty?
      end

      def problem(archive, target, ruby, decision, resolution)
        why = decision.cause ? " (#{decision.cause.chain.join('; ')})" : ""
        Diagnostic.error("gem-ruby", "gem #{archive.name} #{archive.version} needs Ruby #{archive.required_ruby}, and " \
                                     "would be built for #{target} (Ruby #{ruby})#{why}: it would install there but not load",
                         location: GemCheck.location_of(archive.name, resolution),
                         hint: "leave out what needs #{archive.name} on #{target.codename} (leave_out with targets:)")
      end
    end
  end
end
