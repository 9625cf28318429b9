# frozen_string_literal: true

module Relspec
  module Diff
    # An ancestor that provides something else than before on a codename
    # (its content digest changed), was added or was removed; +packages+ are
    # the release's packages whose inherited decision followed.
    AncestorChange = Struct.new(:ancestor, :codename, :change, :packages, keyword_init: true) do
      def to_s
        what = "ancestor #{ancestor} #{change} on #{codename}"
        packages.empty? ? what : "#{what}: #{packages.join(', ')}"
      end

      def to_h
        { "ancestor" => ancestor, "codename" => codename, "change" => change, "packages" => packages }
      end
    end
  end
end
