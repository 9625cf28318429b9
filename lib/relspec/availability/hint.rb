# frozen_string_literal: true

require_relative "../suggestion"

module Relspec
  module Availability
    # A name that does exist on the target, offered next to one that does
    # not. The usual cause is a version in the name (a library's soname, a
    # Boost or LLVM version: libboost-system1.74-dev on one distribution,
    # libboost-system1.83-dev on the next), so names that differ only in
    # their numbers come first; otherwise the spell checker's closest name
    # among those sharing the first letters.
    class Hint
      PREFIX = 4
      # Above this, the spell checker is not asked (it compares every candidate).
      SPELL_CANDIDATES = 5_000

      def initialize(names)
        @names = names
      end

      def for(name)
        same = by_shape[shape(name)]
        return same.max_by { |candidate| numbers(candidate) } if same

        candidates = @names.select { |candidate| candidate.start_with?(name[0, PREFIX]) }
        return nil if candidates.empty? || candidates.size > SPELL_CANDIDATES

        Suggestion.closest(name, candidates)
      end

      private

      def by_shape
        @by_shape ||= @names.group_by { |candidate| shape(candidate) }
      end

      def shape(name)
        name.gsub(/\d+(?:\.\d+)*/, "#")
      end

      # The newest numbers win (1.83 over 1.74).
      def numbers(name)
        name.scan(/\d+/).map(&:to_i)
      end
    end
  end
end
