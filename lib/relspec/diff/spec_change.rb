# frozen_string_literal: true

module Relspec
  module Diff
    # One change of a spec file's own keys: +key+ ("blacklist", "pins",
    # "targets", "parent", or any other top-level key), +change+ ("added",
    # "removed", "moved", "changed"), +subject+ (the blacklist match, the
    # pinned package, the target; nil for whole keys), +old+/+new+ values as
    # text, and +decisions+: the ["codename/arch", package] it caused.
    SpecChange = Struct.new(:key, :change, :subject, :old, :new, :decisions, keyword_init: true) do
      # "blacklist entry base/types added", "pin of base/types moved (tag v1 → tag v2)"
      def to_s
        what = case key
               when "blacklist" then "blacklist entry #{subject}"
               when "leave_out" then "leave_out entry #{subject}"
               when "pins" then "pin of #{subject}"
               when "targets" then "target #{subject}"
               else key
               end
        values = [old, new].compact
        detail = if %w[added removed].include?(change) then values.empty? ? "" : " (#{values.join})"
                 else " (#{old || 'none'} → #{new || 'none'})"
                 end
        "#{what} #{change}#{detail}"
      end

      def to_h
        { "key" => key, "change" => change, "subject" => subject, "old" => old, "new" => new,
          "decisions" => decisions.map { |target, package| { "target" => target, "package" => package } } }.compact
      end
    end
  end
end
