# frozen_string_literal: true

require "json"
require_relative "lock"

module Relspec
  module Plan
    # Renders a ReleasePlan for people: text for terminals, Markdown for pull
    # request comments, JSON for tools (the lock's content).
    class Report
      # +lock+: the Lock of +plan+ (the JSON form is its content).
      def initialize(plan, lock, targets: plan.targets.keys)
        @plan = plan
        @lock = lock
        @targets = targets.sort_by(&:to_s)
      end

      def json
        data = @lock.to_h
        data["targets"] = data["targets"].slice(*@targets.map(&:to_s))
        "#{JSON.pretty_generate(data)}\n"
      end

      def text
        columns = self.columns
        lines = [headline, "", "#{'target'.ljust(22)}#{columns.map { |column| column.to_s.rjust(12) }.join}"]
        @targets.each do |target|
          counts = @plan.counts(target)
          lines << "#{target.to_s.ljust(22)}#{columns.map { |column| counts[column].to_s.rjust(12) }.join}"
        end
        build_groups.each { |targets, builds| lines.concat(build_lines(targets, builds)) }
        other_groups.each do |title, groups|
          groups.each do |targets, texts|
            lines << "" << "#{title} #{targets.join(', ')}:"
            width = texts.keys.map(&:size).max
            texts.each { |name, text| lines << "  #{name.ljust(width)}  #{text}" }
          end
        end
        lines.concat(section("warnings", @plan.warnings.map(&:message)))
        lines.concat(section("notes", @plan.notes))
        "#{lines.join("\n")}\n"
      end

      def markdown
        columns = self.columns
        lines = ["### #{headline}", "", "| target | #{columns.join(' | ')} |", "| --- |#{' ---: |' * columns.size}"]
        @targets.each do |target|
          counts = @plan.counts(target)
          lines << "| #{target} | #{columns.map { |column| counts[column] }.join(' | ')} |"
        end
        build_groups.each do |targets, builds|
          lines << "" << "**Builds on #{targets.join(', ')}**" << ""
          builds.each do |decision|
            lines << "- `#{decision.package}` (`#{decision.deb_name}`): #{decision.cause}#{"; #{decision.cutoff}" if decision.cutoff}"
          end
        end
        other_groups.each do |title, groups|
          groups.each do |targets, texts|
            lines << "" << "**#{title.capitalize} #{targets.join(', ')}**" << ""
            texts.each { |name, text| lines << "- `#{name}`: #{text}" }
          end
        end
        lines.concat(section("**Warnings**", @plan.warnings.map(&:message), bullet: "-"))
        lines.concat(section("**Notes**", @plan.notes, bullet: "-"))
        "#{lines.join("\n")}\n"
      end

      private

      # A group of builds in the text: package, version, why, and whether
      # the early cutoff may keep it.
      def build_lines(targets, builds)
        width = builds.map { |decision| decision.package.size }.max
        ["", "builds on #{targets.join(', ')}:"] + builds.flat_map do |decision|
          ["  #{decision.package.ljust(width)}  #{decision.deb_name} #{short_version(decision)}", "    #{decision.cause}",
           *("    #{decision.cutoff}" if decision.cutoff)]
        end
      end

      def headline
        packages = @plan.packages.size
        ancestors = @lock.ancestors.keys
        "#{@plan.release}: #{packages} packages on #{@targets.size} targets; " \
          "ancestors: #{ancestors.empty? ? 'none' : ancestors.join(', ')}"
      end

      # system and unavailable appear only for releases that have such
      # packages, so plain releases read as they always did.
      def columns
        optional = %i[system unavailable].select { |column| @targets.any? { |target| @plan.counts(target)[column].positive? } }
        %i[inherit build published] + optional
      end

      # Packages that are neither inherited nor built, and published ones
      # the early cutoff kept: [[title, groups]].
      def other_groups
        [["kept by the early cutoff on", kept_groups], ["taken from the distribution on", system_groups],
         ["not available on", unavailable_groups]]
      end

      # Published packages the early cutoff kept when their dependencies
      # were rebuilt, with why (docs/abi.md).
      def kept_groups
        grouped do |target|
          @plan.targets.fetch(target).values.select(&:kept).sort_by(&:package)
               .to_h { |decision| [decision.package, "#{decision.deb_name} #{decision.version}: #{decision.kept}"] }
        end
      end

      def unavailable_groups
        grouped { |target| @plan.unavailable.fetch(target).transform_values(&:to_s) }
      end

      def system_groups
        grouped do |target|
          @plan.targets.fetch(target).values.select(&:system?).sort_by(&:package)
               .to_h { |decision| [decision.package, "#{decision.deb_name} #{decision.version}"] }
        end
      end

      # [[targets, {package => text}]]: targets with the same texts are shown once.
      def grouped
        groups = Hash.new { |hash, key| hash[key] = [] }
        @targets.each do |target|
          texts = yield(target)
          groups[texts] << target.to_s unless texts.empty?
        end
        groups.map { |texts, targets| [targets, texts] }
      end

      # Targets whose builds (packages and causes) are the same are shown once.
      def build_groups
        groups = Hash.new { |hash, key| hash[key] = [] }
        @targets.each do |target|
          builds = @plan.builds(target).sort_by(&:package)
          next if builds.empty?

          key = builds.map do |decision|
            [decision.package, decision.deb_name, decision.cause.to_s, short_version(decision), decision.cutoff.to_s]
          end
          groups[key] << [target, builds]
        end
        groups.values.map { |entries| [entries.map { |target, _| target.to_s }, entries.first[1]] }
      end

      # The version without its ~codename, the same on every target.
      def short_version(decision)
        decision.version.to_s.sub(/~[a-z0-9-]+\z/, "")
      end

      def section(title, items, bullet: " ")
        return [] if items.empty?

        ["", "#{title}#{':' unless title.start_with?('**')}", *items.map { |item| "#{bullet} #{item}" }]
      end
    end
  end
end
