# frozen_string_literal: true

require "json"
require_relative "spec_change"

module Relspec
  module Diff
    # Which keys of a spec file changed (blacklist entries, pins, targets,
    # parent, anything else), each linked to the decision changes it caused.
    module SpecChanges
      # Keys compared entry by entry; the others are compared whole.
      DETAILED = %w[blacklist leave_out pins targets parent release].freeze

      module_function

      # +old+, +new+: the spec files' data (Hash, or nil when unknown);
      # +targets+: the release's TargetDiffs.
      def compare(old, new, targets)
        return [] unless old.is_a?(Hash) && new.is_a?(Hash)

        changes = release(old, new) + matches("blacklist", old, new) + matches("leave_out", old, new) + pins(old, new) + target_keys(old, new) + parent(old, new) +
                  others(old, new)
        changes.map { |change| SpecChange.new(**change, decisions: linked(change, targets)).freeze }
      end

      # A renamed release (its spec file renamed with it).
      def release(old, new)
        return [] if old["release"] == new["release"]

        [{ key: "release", change: "changed", subject: nil, old: text(old["release"]), new: text(new["release"]) }]
      end

      # Entries of a list of {match, reason} (blacklist, leave_out), by match.
      def matches(key, old, new)
        before = entries(old[key])
        after = entries(new[key])
        (before.keys | after.keys).sort.filter_map do |match|
          a = before[match]
          b = after[match]
          next if a == b

          change = if a.nil?
                     "added"
                   elsif b.nil?
                     "removed"
                   else
                     "changed"
                   end
          reason = ->(entry) { entry && entry["reason"] ? entry["reason"].to_s : nil }
          { key: key, change: change, subject: match, old: (reason.call(a) unless change == "added"),
            new: (reason.call(b) unless change == "removed") }
        end
      end

      def entries(list)
        Array(list).select { |entry| entry.is_a?(Hash) && entry["match"] }.to_h { |entry| [entry["match"].to_s, entry] }
      end

      def pins(old, new)
        before = hash(old["pins"])
        after = hash(new["pins"])
        (before.keys | after.keys).sort.filter_map do |package|
          next if before[package] == after[package]

          change = if !before.key?(package)
                     "added"
                   elsif !after.key?(package)
                     "removed"
                   else
                     "moved"
                   end
          { key: "pins", change: change, subject: package, old: pin_text(before[package]), new: pin_text(after[package]) }
        end
      end

      def pin_text(pin)
        pin.is_a?(Hash) ? pin.map { |ref, value| "#{ref} #{value}" }.join(", ") : pin&.to_s
      end

      def target_keys(old, new)
        before = target_list(old["targets"])
        after = target_list(new["targets"])
        (after - before).map { |target| { key: "targets", change: "added", subject: target } } +
          (before - after).map { |target| { key: "targets", change: "removed", subject: target } }
      end

      def target_list(targets)
        hash(targets).flat_map { |codename, archs| Array(archs).map { |arch| "#{codename}/#{arch}" } }.sort
      end

      def parent(old, new)
        before = Array(old["parent"]).map(&:to_s)
        after = Array(new["parent"]).map(&:to_s)
        return [] if before == after

        [{ key: "parent", change: "changed", subject: nil, old: before.empty? ? nil : before.join(", "),
           new: after.empty? ? nil : after.join(", ") }]
      end

      def others(old, new)
        (old.keys | new.keys).map(&:to_s).sort.filter_map do |key|
          next if DETAILED.include?(key) || old[key] == new[key]

          { key: key, change: "changed", subject: nil, old: text(old[key]), new: text(new[key]) }
        end
      end

      def text(value)
        value.nil? || value.is_a?(String) ? value : JSON.generate(value)
      end

      def hash(value)
        value.is_a?(Hash) ? value.transform_keys(&:to_s) : {}
      end

      # The decision changes a spec change explains.
      def linked(change, targets)
        targets.flat_map do |target|
          target.changes.select { |package_change| explains?(change, target, package_change) }
                .map { |package_change| [target.target, package_change.package] }
        end
      end

      def explains?(change, target, package_change)
        case change[:key]
        when "blacklist" then caused_by?(package_change, "blacklisted by \"#{change[:subject]}\"")
        when "leave_out" then caused_by?(package_change, "left out by \"#{change[:subject]}\"")
        when "pins" then [package_change.old, package_change.new].compact.any? do |decision|
          decision.root_package(package_change.package) == change[:subject] && root_pinned?(decision)
        end || package_change.package == change[:subject]
        when "targets" then target.target == change[:subject]
        when "parent" then ancestry?(package_change)
        else false
        end
      end

      def caused_by?(package_change, cause)
        [package_change.old, package_change.new].compact.any? do |decision|
          decision.root_cause.to_s.start_with?(cause)
        end
      end

      def root_pinned?(decision)
        !decision.built? || decision.root_cause.to_s.start_with?("pinned to")
      end

      # Changes that follow from which ancestors there are.
      def ancestry?(package_change)
        return true if package_change.kind == "ancestor"

        [package_change.old, package_change.new].compact.any? do |decision|
          decision.inherited? || decision.root_cause.to_s.match?(/\A(missing in all ancestors|no ancestor has target)/)
        end
      end
    end
  end
end
