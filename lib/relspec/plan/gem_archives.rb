# frozen_string_literal: true

require_relative "distribution_packages"
require_relative "../debian/naming"

module Relspec
  module Plan
    # The targets' own ruby-* packages (DistributionPackages), read at most
    # once for planning's two uses of them: loading the catalog asks for all
    # of them (#call, and #depends) when it resolves a gem of the release
    # against what the distributions have; the Planner then needs only the Debian names of
    # the release's gems (#distribution), and those are read only when the
    # whole set was not.
    class GemArchives
      # +read+: called with the wanted names (or a Regexp), returns a
      # DistributionPackages.
      def initialize(targets, &read)
        @targets = targets
        @read = read
      end

      # {target name => {ruby-* name => [versions]}} of every target, as
      # Catalog::ReleaseCatalog.load's +gem_archives+ asks for them.
      def call
        @all ||= @read.call(Debian::Naming::DISTRIBUTION_GEMS)
        @targets.to_h { |target| [target.to_s, @all.index(target)] }
      end

      # {target name => {gem package => Catalog::GemDepends}} of every
      # target (what depends on what among its gem packages), read with #call.
      def depends
        call
        @targets.to_h { |target| [target.to_s, @all.gem_depends(target)] }
      end

      # The packages of +wanted+ (Debian names): those already read, else read now.
      def distribution(wanted)
        @all || @read.call(wanted)
      end
    end
  end
end
