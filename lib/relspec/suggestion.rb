# frozen_string_literal: true

require "did_you_mean"

module Relspec
  # "did you mean" hints, from the same spell checker Ruby uses for its own
  # NameErrors, so a typo in a spec gets the help a typo in code gets.
  module Suggestion
    module_function

    def closest(word, candidates)
      DidYouMean::SpellChecker.new(dictionary: candidates.map(&:to_s)).correct(word.to_s).first
    end

    def hint(word, candidates)
      found = closest(word, candidates)
      found && "did you mean \"#{found}\"?"
    end
  end
end
