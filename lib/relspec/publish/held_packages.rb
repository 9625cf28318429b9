# frozen_string_literal: true

require_relative "../target"
require_relative "../plan/decision"
require_relative "../apt/version"

module Relspec
  module Publish
    # What a published release's repository osdeps files list, from the
    # facts that exist after publishing: the decisions of the release's lock
    # and what the repositories hold now. An entry is listed only when apt
    # can install it: a build or published package when the release's own
    # repository holds its Debian name at the locked version, an inherited
    # one when the ancestor it came from does, a distribution's gem
    # (system) as the lock says. Unavailable packages have no Debian name.
    module HeldPackages
      # +targets+: Target => {package => Plan::Decision}, what Osdeps::Files
      # writes; +missing+: "target package (deb version)" of each locked
      # package the repositories do not hold.
      Listing = Struct.new(:targets, :missing, keyword_init: true)

      OWN = %w[build published].freeze

      module_function

      # +lock+: Plan::Lock; +own+: what the release's repository holds
      # (#version_of(deb, target), Plan::OwnRepository); +inventory+: what
      # the ancestors' repositories hold (#index(ancestor, target),
      # Plan::Inventory). Reads nothing.
      def list(lock, own:, inventory:)
        missing = []
        targets = lock.targets.sort.to_h do |name, entries|
          target = Target.parse(name)
          held = entries.sort.filter_map do |package, entry|
            next if entry.decision == "unavailable"
            next [package, decision(package, entry)] if held?(entry, target, own, inventory)

            missing << "#{target} #{package} (#{entry.deb} #{entry.version})"
            nil
          end
          [target, held.to_h]
        end
        Listing.new(targets: targets, missing: missing).freeze
      end

      def held?(entry, target, own, inventory)
        case entry.decision
        when "system" then true
        when "inherit" then same_version?(inventory.index(entry.from, target)&.[](entry.deb)&.version, entry.version)
        else OWN.include?(entry.decision) && same_version?(own.version_of(entry.deb, target), entry.version)
        end
      end

      # Both versions equal by dpkg's rules ("1.0-1" and "1.0-01" are one).
      def same_version?(held, locked)
        !held.nil? && Apt::Version.parse(held.to_s) == Apt::Version.parse(locked.to_s)
      end

      def decision(package, entry)
        entry.to_decision(package)
      end
      private_class_method :held?, :same_version?, :decision
    end
  end
end
