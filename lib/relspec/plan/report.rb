# frozen_string_literal: true

require "json"
require_relative "lock"

module Relspec
  module Plan
    # Renders a ReleasePlan for people: text for terminals, Markdown for pull
    # request comments, JSON for tools (the lock's content).
    class Report
      def initialize(plan, spec_digest, targets: plan.targets.keys)
        @plan = plan
        @spec_digest = spec_digest
        @targets = targets.sort_by(&:to_s)
      end

      def json
        data = Lock.to_h(@plan, @spec_digest)
        data["targets"] = data["targets"].slice(*@targets.map(&:to_s))
        "#{JSON.pretty_generate(data)}\n"
      end

      def text
        lines = [headline, "", format("%-22s %8s %6s %10s%s", "target", "inherit", "build", "published", unavailable_column)]
        @targets.each do |target|
          counts = @plan.counts(target)
          lines << format("%-22s %8d %6d %10d%s", target, counts[:inherit], counts[:build], counts[:published],
                          unavailable_column(counts))
        end
        build_groups.each do |targets, builds|
          lines << "" << "builds on #{targets.join(', ')}:"
          width = builds.map { |decision| decision.package.size }.max
          builds.each do |decision|
            lines << "  #{decision.package.ljust(width)}  #{decision.deb_name} #{short_version(decision)}"
            lines << "    #{decision.cause}"
          end
        end
        unavailable_groups.each do |targets, causes|
          lines << "" << "not available on #{targets.join(', ')}:"
          width = causes.keys.map(&:size).max
          causes.each { |name, cause| lines << "  #{name.ljust(width)}  #{cause}" }
        end
        lines.concat(section("warnings", @plan.warnings.map(&:message)))
        lines.concat(section("notes", @plan.notes))
        "#{lines.join("\n")}\n"
      end

      def markdown
        gaps = unavailable?
        lines = ["### #{headline}", "", "| target | inherit | build | published |#{' unavailable |' if gaps}",
                 "| --- | ---: | ---: | ---: |#{' ---: |' if gaps}"]
        @targets.each do |target|
          counts = @plan.counts(target)
          lines << "| #{target} | #{counts[:inherit]} | #{counts[:build]} | #{counts[:published]} |" \
                   "#{" #{counts[:unavailable]} |" if gaps}"
        end
        build_groups.each do |targets, builds|
          lines << "" << "**Builds on #{targets.join(', ')}**" << ""
          builds.each { |decision| lines << "- `#{decision.package}` (`#{decision.deb_name}`): #{decision.cause}" }
        end
        unavailable_groups.each do |targets, causes|
          lines << "" << "**Not available on #{targets.join(', ')}**" << ""
          causes.each { |name, cause| lines << "- `#{name}`: #{cause}" }
        end
        lines.concat(section("**Warnings**", @plan.warnings.map(&:message), bullet: "-"))
        lines.concat(section("**Notes**", @plan.notes, bullet: "-"))
        "#{lines.join("\n")}\n"
      end

      private

      def headline
        packages = @plan.packages.size
        ancestors = Lock.ancestors(@plan).keys
        "#{@plan.release}: #{packages} packages on #{@targets.size} targets; " \
          "ancestors: #{ancestors.empty? ? 'none' : ancestors.join(', ')}"
      end

      # The column appears only for releases with packages some target
      # cannot have, so plain releases read as before.
      def unavailable_column(counts = nil)
        return "" unless unavailable?

        counts ? format(" %11d", counts[:unavailable]) : format(" %11s", "unavailable")
      end

      def unavailable?
        @targets.any? { |target| !@plan.unavailable.fetch(target).empty? }
      end

      # Targets lacking the same packages for the same reasons are shown once.
      def unavailable_groups
        groups = Hash.new { |hash, key| hash[key] = [] }
        @targets.each do |target|
          causes = @plan.unavailable.fetch(target).transform_values(&:to_s)
          groups[causes] << target.to_s unless causes.empty?
        end
        groups.map { |causes, targets| [targets, causes] }
      end

      # Targets whose builds (packages and causes) are the same are shown once.
      def build_groups
        groups = Hash.new { |hash, key| hash[key] = [] }
        @targets.each do |target|
          builds = @plan.builds(target).sort_by(&:package)
          next if builds.empty?

          key = builds.map { |decision| [decision.package, decision.deb_name, decision.cause.to_s, short_version(decision)] }
          groups[key] << [target, builds]
        end
        groups.values.map { |entries| [entries.map { |target, _| target.to_s }, entries.first[1]] }
      end

      # The version without its ~codename, the same on every target.
      def short_version(decision)
        decision.version.sub(/~[a-z0-9-]+\z/, "")
      end

      def section(title, items, bullet: " ")
        return [] if items.empty?

        ["", "#{title}#{':' unless title.start_with?('**')}", *items.map { |item| "#{bullet} #{item}" }]
      end
    end
  end
end
