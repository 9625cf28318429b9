# frozen_string_literal: true

module Relspec
  module Osdeps
    # What the repositories really hold, for osdeps files that list only
    # installable packages (`osdeps --from-repository`, `publish`): a
    # planned build is not there yet; inherited and published packages are.
    class RepositoryPresence
      attr_reader :missing

      def initialize
        @missing = []
      end

      # The filter Renderer.render takes as +present:+.
      def to_proc
        lambda do |target, decision|
          held = !decision.build?
          @missing << "#{target} #{decision.package} (#{decision.deb_name} #{decision.version})" unless held
          held
        end
      end
    end
  end
end
