# frozen_string_literal: true

require_relative "../frozen"
require_relative "../debian/naming"

module Relspec
  class Catalog
    # Which gem packages of a distribution the release's own gems shadow on
    # one target. The release installs its gems where Ruby finds them first
    # (RUBYLIB), so a distribution gem that depends on a gem the release
    # packages itself (ruby-dry-types 1.2.2 on trixie, made for Debian's
    # dry-core 0.7, beside the release's dry-core 1.2.0) runs against a
    # version it was never made for: it cannot be taken from the
    # distribution. Debian's Depends say what a distribution gem runs with
    # (its version constraints do not: ruby-dry-types asks for
    # ruby-dry-core >= 0.4.4 and breaks with 1.2.0), so any packaged gem it
    # reaches through them, directly or through other gem packages, shadows it.
    class ShadowedGems
      # Why a distribution gem cannot be taken: +deb+ at +version+ on
      # +codename+ reaches, through the gem packages +via+, gem +gem+, which
      # the release packages at +packaged+.
      Shadowing = Struct.new(:deb, :version, :codename, :via, :gem, :packaged, keyword_init: true) do
        def initialize(**fields)
          super(**fields.transform_values { |value| Frozen.deep(value) })
          freeze
        end

        def to_s
          steps = via.map { |name| "depends on #{name}, which " }.join
          "#{deb} #{version} (#{codename}) #{steps}depends on #{gem}, which the release packages at #{packaged}"
        end
      end

      # +depends+: gem package name => GemDepends of the target's archive;
      # +packaged+: gem name => the version the release packages it at
      # there; +codename+: the target's.
      def initialize(depends:, packaged:, codename:)
        @depends = depends
        @packaged = packaged.to_h { |gem, version| [Debian::Naming.distribution_gem(gem), [gem, version]] }
        @codename = codename
        freeze
      end

      # The Shadowing of gem package +deb+ (breadth first: a shortest
      # chain, the first by name), nil when it reaches no packaged gem or
      # the archive has no such package.
      def of(deb)
        start = @depends[deb]
        return nil unless start

        paths = { deb => [] }
        frontier = [deb]
        until frontier.empty?
          reached = []
          frontier.each do |name|
            @depends[name]&.depends&.each do |other|
              next if paths.key?(other)

              return shadowing(start, paths[name], other) if @packaged.key?(other)

              paths[other] = paths[name] + [other]
              reached << other
            end
          end
          frontier = reached.sort
        end
        nil
      end

      private

      def shadowing(start, via, deb)
        gem, version = @packaged.fetch(deb)
        Shadowing.new(deb: start.name, version: start.version, codename: @codename, via: via, gem: gem, packaged: version)
      end
    end
  end
end
