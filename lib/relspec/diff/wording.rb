# frozen_string_literal: true

module Relspec
  module Diff
    # How decisions and changes read in text and Markdown (one wording for both).
    module Wording
      module_function

      # "inherit rock-demo-base-base-types 2.0.20200601.103000-1~bionic from demo-base"
      def decision(decision)
        return "none" unless decision
        return "unavailable" if decision.kind == "unavailable"

        from = decision.from ? " from #{decision.from}" : ""
        "#{decision.kind} #{decision.deb} #{decision.version}#{from}"
      end

      # What a change did, old → new, with the commit range when known.
      def change(change)
        text = case change.kind
               when "added" then decision(change.new)
               when "removed" then "was #{decision(change.old)}"
               when "cause" then "#{decision(change.new)} (for another reason)"
               else "#{decision(change.old)} → #{decision(change.new)}"
               end
        change.commits ? "#{text}; commits #{change.commits}" : text
      end

      # The cause chain on one line, nearest step first; for a new revision
      # of the same source, why it was rebuilt comes first.
      def causes(change)
        # newly kept by the early cutoff (docs/abi.md): why, rather than the causes of the build it kept
        return "kept at #{change.new.version}: #{change.new.kept}" if change.new&.kept && change.old&.kept != change.new.kept

        chain = change.causes.join(" ← ")
        return chain unless change.rebuilt_because

        reason = rebuilt_because(change)
        chain.empty? ? reason : "#{reason}; built because #{chain}"
      end

      # "rebuilt with the same source because base/types changed version (… → …)"
      def rebuilt_because(change)
        "rebuilt with the same source because #{change.rebuilt_because}"
      end

      # "3 decisions (bionic/amd64, buster/amd64)"
      def decisions(pairs)
        return "no decision changed" if pairs.empty?

        targets = pairs.map(&:first).uniq
        "#{pairs.size} decision#{'s' unless pairs.size == 1} (#{targets.join(', ')})"
      end
    end
  end
end
