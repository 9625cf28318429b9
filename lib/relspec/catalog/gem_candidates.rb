# frozen_string_literal: true

require_relative "target_rubies"

module Relspec
  class Catalog
    # The version of a gem to package, best first: the lock's while it fits
    # (as Bundler keeps a Gemfile.lock), else the highest of gem_source that
    # fits, where fitting includes every target's Ruby. The compact index's
    # word on a version's Ruby spares downloading a .gem that cannot fit;
    # the .gem's own gemspec decides.
    class GemCandidates
      # +versions+: GemVersions; +fetch+: (name, version) → GemArchive;
      # +rubies+: TargetRubies; +locked+: name => the version the lock recorded.
      def initialize(versions:, fetch:, rubies:, locked:)
        @versions = versions
        @fetch = fetch
        @rubies = rubies
        @locked = locked
      end

      # The GemArchive of the best version of +name+ the block accepts
      # (a Gem::Version) and every Ruby of +rubies+ (default: every
      # target's) runs, or nil; +refused+ gets [version, Gem::Requirement on
      # Ruby] of each one passed over for its Ruby. Raises
      # GemArchive::Problem and GemVersions::Problem.
      def best(name, refused, rubies = @rubies, &fits)
        candidates(name, fits).each do |version|
          hinted = @versions.required_ruby(name, version)
          next refused << [version, hinted] unless rubies.refusing(hinted).empty?

          archive = @fetch.call(name, version)
          return archive if rubies.refusing(archive.required_ruby).empty?

          refused << [version, archive.required_ruby]
        end
        nil
      end

      private

      # gem_source is listed only when the lock's version does not do.
      def candidates(name, fits)
        locked = @locked[name]
        Enumerator.new do |yielder|
          yielder << locked if locked && Gem::Version.correct?(locked) && fits.call(Gem::Version.new(locked))
          @versions.of(name).each { |version| yielder << version.to_s if fits.call(version) && version.to_s != locked }
        end
      end
    end
  end
end
