# frozen_string_literal: true

require "rubygems/requirement"
require_relative "package_version"
require_relative "gem_version"

module Relspec
  module Debian
    # An osdeps gem constraint (`rice<4.0.0`, `foo~>1.2`) as Debian relations
    # on the distribution's package of that gem, so that apt cannot later
    # replace it with a version autoproj would never have installed
    # (ruby-rice 4 under bindings written for the Rice 3 API).
    module GemRelations
      # Gem operator => Debian operator; `!=` has no Debian relation.
      OPERATORS = { "=" => "=", ">" => ">>", "<" => "<<", ">=" => ">=", "<=" => "<=" }.freeze

      module_function

      # +deb+: the Debian package ("ruby-rice"); +constraint+: the text after
      # the gem's name in the osdeps entry ("<4.0.0", "", "~> 1.2").
      # One relation per bound; the bare name when nothing can be said.
      def of(deb, constraint)
        relations = requirement(constraint)&.requirements&.flat_map { |op, version| bounds(deb, op, version) } || []
        relations.empty? ? [deb] : relations.uniq
      end

      def requirement(constraint)
        text = constraint.strip
        text.empty? ? nil : Gem::Requirement.new(*text.split(",").map(&:strip))
      rescue Gem::Requirement::BadRequirementError
        nil
      end

      # `~> 1.2` is ">= 1.2 and < 2": RubyGems' own reading of it (bump).
      def bounds(deb, operator, version)
        return [] if operator == ">=" && version.segments.all?(&:zero?) # RubyGems' "any version"
        if operator == "~>"
          return ["#{deb} (>= #{GemVersion.to_debian(version)})", "#{deb} (<< #{GemVersion.to_debian(version.bump)})"]
        end

        debian = OPERATORS[operator]
        debian ? ["#{deb} (#{debian} #{GemVersion.to_debian(version)})"] : []
      end
    end
  end
end
