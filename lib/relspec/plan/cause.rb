# frozen_string_literal: true

require_relative "../printable"

module Relspec
  module Plan
    # Why a package is built in this release, or why it cannot exist on a
    # target. Causes chain: a package rebuilt (or left out) because of one of
    # its dependencies carries that dependency's cause, so every rebuild can
    # be traced to a spec entry or a fact about the ancestors, and every gap
    # to an osdeps entry. Text from the spec or the workspace (matches,
    # reasons, refs, osdeps names) is kept Printable: causes are printed by
    # `plan` and `why`, one per line.
    class Cause
      attr_reader :kind, :detail, :because

      def self.missing
        new(:missing, nil, nil)
      end

      def self.no_ancestor_target(target)
        new(:no_ancestor_target, target.to_s, nil)
      end

      def self.blacklisted(match, reason)
        new(:blacklisted, reason ? "\"#{Printable.text(match)}\" (#{Printable.text(reason)})" : "\"#{Printable.text(match)}\"", nil)
      end

      def self.pinned(commit, ref)
        new(:pinned, ref ? "#{Printable.text(commit)} (#{Printable.text(ref)})" : Printable.text(commit), nil)
      end

      def self.gem_version(version, ancestor, theirs)
        new(:gem_version, "#{version} (#{ancestor} has #{theirs})", nil)
      end

      # A gem the distribution has, which the release's own gems would
      # shadow (+shadowing+: Catalog::ShadowedGems::Shadowing).
      def self.shadowed_gem(shadowing)
        new(:shadowed_gem, Printable.text(shadowing.to_s), nil)
      end

      def self.depends_on(package, cause)
        new(:depends_on, package, cause)
      end

      def self.nonexistent_osdeps(osdeps, codename)
        plural = osdeps.size > 1
        new(:nonexistent_osdeps, "#{plural ? 'osdeps' : 'osdep'} #{osdeps.map { |name| Printable.text(name) }.join(', ')} " \
                                 "#{plural ? 'are' : 'is'} " \
                                 "nonexistent on #{codename}", nil)
      end

      # autoproj excludes the package (+reason+: autoproj's words).
      def self.excluded(reason)
        new(:excluded, Printable.text(reason), nil)
      end

      # OS dependencies the osdeps files define for other systems only.
      def self.other_os_osdeps(osdeps, codename)
        new(:other_os_osdeps, "#{osdeps.size > 1 ? 'osdeps' : 'osdep'} #{osdeps.map { |name| Printable.text(name) }.join(', ')} " \
                              "#{osdeps.size > 1 ? 'are' : 'is'} defined for other systems only, not #{codename}", nil)
      end

      def self.left_out(match, reason)
        new(:left_out, "\"#{Printable.text(match)}\" (#{Printable.text(reason)})", nil)
      end

      def self.unavailable_dependency(package, cause)
        new(:unavailable_dependency, package, cause)
      end

      # A chain's lines (+chain+: #chain, or a lock's causes) as `relspec
      # why` and the report show them: each step indented under the one it
      # explains.
      def self.steps(chain)
        chain.each_with_index.map { |step, depth| "#{'  ' * (depth + 1)}#{'└ ' if depth.positive?}#{step}" }
      end

      def initialize(kind, detail, because)
        @kind = kind
        @detail = detail
        @because = because
        freeze
      end

      # How many dependency steps lead to the original cause.
      def depth
        because ? 1 + because.depth : 0
      end

      # The original cause at the end of the chain.
      def root
        because ? because.root : self
      end

      def to_s
        case kind
        when :missing then "missing in all ancestors"
        when :no_ancestor_target then "no ancestor has target #{detail}"
        when :blacklisted then "blacklisted by #{detail}"
        when :pinned then "pinned to #{detail}"
        when :gem_version then "gem version #{detail}"
        when :shadowed_gem then "not taken from the distribution: #{detail}"
        when :depends_on then "depends on #{detail}, which is rebuilt because #{because}"
        when :nonexistent_osdeps, :other_os_osdeps then detail
        when :excluded then "excluded by autoproj: #{detail}"
        when :left_out then "left out by #{detail}"
        when :unavailable_dependency then "depends on #{detail}, which is unavailable because #{because}"
        end
      end

      # One line per step, for the lock file and `relspec why`.
      def chain
        because ? ["depends on #{detail}", *because.chain] : [to_s]
      end
    end
  end
end
