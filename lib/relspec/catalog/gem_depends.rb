# frozen_string_literal: true

require_relative "../frozen"

module Relspec
  class Catalog
    # One gem package of a distribution's archive (ruby-dry-types 1.2.2-1 on
    # trixie) and the gem packages its Depends name (ruby-dry-core, …):
    # what ShadowedGems follows.
    GemDepends = Struct.new(:name, :version, :depends, keyword_init: true) do
      def initialize(name:, version:, depends:)
        super(name: Frozen.deep(name), version: Frozen.deep(version), depends: Frozen.deep(depends))
        freeze
      end
    end
  end
end
