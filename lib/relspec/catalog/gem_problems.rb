# frozen_string_literal: true

require_relative "target_rubies"
require_relative "../diagnostic"

module Relspec
  class Catalog
    # How GemResolution says that a gem has no version to package: each
    # names the gem, what asks for it and what gem_source has.
    module GemProblems
      module_function

      # +asked+: [[Gem::Requirement, who asks]]; +versions+: GemVersions;
      # +shadowing+: why it is not taken from the distribution, or nil.
      def unresolvable(name, asked, versions, shadowing:, location:)
        listed = versions.of(name)
        there = listed.empty? ? "it has none" : "it has #{listed.first(5).join(', ')}#{', …' if listed.size > 5}"
        shadowed = " (not taken from the distribution: #{shadowing})" if shadowing
        Diagnostic.error("gem-unresolvable", "no version of gem #{name} in #{versions.where} fits what is asked: " \
                                             "#{describe(asked)}; #{there}#{shadowed}",
                         location: location, hint: fetch_hint(name, asked, versions))
      end

      # Every version that fits what is asked needs a Ruby some target
      # lacks: +refused+ is [[version, Gem::Requirement on Ruby]], newest
      # first; +rubies+: TargetRubies.
      def ruby_refused(name, asked, versions, refused, rubies, location:)
        needs = refused.first(3).map { |version, requirement| "#{version} needs Ruby #{requirement}" }
        needs << "…" if refused.size > 3
        targets = TargetRubies.describe(refused.flat_map { |_, requirement| rubies.refusing(requirement) }.uniq.sort)
        Diagnostic.error("gem-ruby", "no version of gem #{name} in #{versions.where} that fits what is asked " \
                                     "(#{describe(asked)}) runs on #{targets}: #{needs.join(', ')}",
                         location: location, hint: "what asks for #{name} cannot run on that Ruby: leave it out there " \
                                                   "(leave_out with targets:)")
      end

      def describe(asked)
        asked.map { |requirement, who| "#{who} (#{requirement})" }.join(", ")
      end

      # Offline, a folder source is filled by hand: say how. Every gem
      # missing at this depth is its own error of the same run; what they
      # need in turn is known only from their .gem, hence `gem install`,
      # which fetches the whole closure at once.
      def fetch_hint(name, asked, versions)
        return "add a fitting #{name} to gem_source, or pin one with gems:" unless versions.folder?

        requirement = asked.map(&:first).reject(&:none?).flat_map(&:as_list).uniq.join(", ")
        version = requirement.empty? ? "" : " -v '#{requirement}'"
        "fetch it into #{versions.where}: `gem fetch #{name}#{version}`; with the gems it needs: " \
          "`gem install --install-dir <dir> --no-document #{name}#{version}`, then copy <dir>/cache/*.gem there"
      end
    end
  end
end
