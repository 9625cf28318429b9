# frozen_string_literal: true

require_relative "../yaml/writer"

module Relspec
  module Osdeps
    # Renders a release's osdeps files in the rock-osdeps package set format
    # (docs/osdeps.md): one file per architecture mapping every autoproj package
    # the release provides — built here or inherited, under the Debian name
    # of the release that holds it — to its Debian package, keyed by
    # distribution type ("ubuntu,debian" / "debian") and labels.
    module Renderer
      module_function

      # +decisions+: Target => {package => Plan::Decision} (a ReleasePlan's
      # targets, or what publish read back); +distributions+: codename =>
      # ReleaseSpec::Distribution; +present+: optional filter (target,
      # decision) → bool, to leave out what a repository does not hold.
      # Returns {arch => YAML text}.
      def render(decisions, distributions, present: ->(_target, _decision) { true })
        by_arch = decisions.keys.group_by(&:arch)
        by_arch.keys.sort.to_h do |arch|
          [arch, Yaml::Writer.dump(entries(decisions, by_arch[arch], distributions, present))]
        end
      end

      def entries(decisions, targets, distributions, present)
        entries = Hash.new { |hash, key| hash[key] = {} }
        targets.sort_by(&:to_s).each do |target|
          distribution = distributions.fetch(target.codename)
          decisions.fetch(target).each do |package, decision|
            next unless present.call(target, decision)

            by_type = entries[package][distribution.osdeps_type_key] ||= {}
            by_type[distribution.osdeps_labels_key] = decision.deb_name
          end
        end
        entries.sort.to_h { |package, by_type| [package, sort_types(by_type)] }
      end

      # "ubuntu,debian" before "debian", as the published files have it;
      # labels in target order.
      def sort_types(by_type)
        by_type.sort_by { |type, _| [type == "debian" ? 1 : 0, type] }.to_h
      end

      def file_name(release, arch)
        "#{release}-#{arch}.yml"
      end
    end
  end
end
