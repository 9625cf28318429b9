# frozen_string_literal: true

require_relative "gem_archive"
require_relative "gem_versions"
require_relative "shadowed_gems"
require_relative "gem_candidates"
require_relative "gem_problems"
require_relative "../apt/version"
require_relative "../debian/naming"
require_relative "../debian/gem_version"
require_relative "../diagnostic"
require_relative "../error"

module Relspec
  class Catalog
    # Which gems the release packages without being told: every external
    # Ruby gem a package requires becomes part of the binary release
    # (docs/compile.md, Gem resolution). A gem osdep of a
    # selected package, and a runtime dependency of a gem the release
    # packages, is:
    #
    # - the distribution's ruby-<gem> when every target whose archive was
    #   read has it at a version all the requirements on it accept, unless
    #   one of them has it depending on a gem the release packages
    #   (ShadowedGems: the release's copy would shadow the one it was made for);
    # - otherwise packaged here, at the version the lock recorded while it
    #   still fits (as Bundler keeps a Gemfile.lock), else the highest one
    #   of gem_source that fits; its own runtime dependencies are resolved
    #   the same way. "Fits" includes the Ruby of every target (the gem's
    #   required_ruby_version): one version serves every target, as one
    #   commit of a workspace package does.
    #
    # `gems:` pins a version and is never second-guessed. Targets without
    # an archive are not checked (one note): their gem osdeps stay ruby-<gem>
    # unless another target makes the gem a package. Choices are greedy, with
    # no backtracking: a gem is chosen again when a later requirement
    # excludes its version, and versions that still do not fit together are
    # the `gem-requirement` error of ReleaseGems. A dependency cycle ends
    # the walk at the first gem seen twice; among gems the release packages
    # it is an error (`gem-cycle`): each would build-depend on the other.
    class GemResolution
      # +automatic+: name => version of the gems packaged without `gems:`;
      # +requirements+: name => [Gem::Requirement] asked of each of them
      # (the planner takes the distribution's package on a target whose
      # version fits them all); +provided+: `gems:` entries every target's
      # distribution has at that version (their .gem is never fetched).
      Result = Struct.new(:automatic, :requirements, :provided, :notes, keyword_init: true)

      NONE = Result.new(automatic: {}, requirements: {}, provided: [], notes: []).freeze

      # +selected+: codename => the selected package names of +catalog+;
      # +pinned+: `gems:`; +archives+: target name => {ruby-* name =>
      # [versions, newest first] (or one version)}, nil for a target whose
      # archive was not read (or a callable
      # giving that); +locked+: name
      # => the version the lock recorded; +versions+: GemVersions; +fetch+:
      # (name, version) → GemArchive; +blacklisted+: name → bool;
      # +location+: where gem_source is set (for errors); +depends+: target
      # name => {gem package => GemDepends} of its archive (or a callable
      # giving that, read with +archives+); +rubies+: TargetRubies;
      # +locate+: name → the Location of its `gems:` entry (or nil).
      def initialize(catalog:, selected:, pinned:, archives:, locked:, versions:, fetch:, blacklisted:, location:, depends: {},
                     rubies: TargetRubies::NONE, locate: ->(_) {})
        @catalog = catalog
        @selected = selected
        @pinned = pinned
        @archives = archives
        @depends = depends
        @versions = versions
        @fetch = fetch
        @blacklisted = blacklisted
        @location = location
        @rubies = rubies
        @locate = locate
        @candidates = GemCandidates.new(versions: versions, fetch: fetch, rubies: rubies, locked: locked)
      end

      # Raises InvalidInput when a gem has no version that fits.
      def call
        requests = osdep_requests
        return NONE if requests.empty? && @pinned.empty?

        # read only now: a release without gems never reads its distribution's archive
        @archives = @archives.call if @archives.respond_to?(:call)
        @depends = @depends.call if @depends.respond_to?(:call)
        @requests = requests
        @chosen = {}
        @needs = {}
        @shadowed = {}
        @spared = {}
        @problems = []
        walk((requests.keys + @pinned.keys).uniq.sort)
        unshadow
        check_cycles
        raise InvalidInput, @problems unless @problems.empty?

        automatic = @chosen.reject { |name, version| version == :system || @pinned.key?(name) }.sort.to_h
        Result.new(automatic: automatic, requirements: automatic.to_h { |name, _| [name, @requests[name].map(&:first)] },
                   provided: @pinned.keys.select { |name| @chosen[name] == :system }.sort, notes: notes).freeze
      end

      private

      # gem name => [[Gem::Requirement, who asks]] from the selected packages' osdeps.
      def osdep_requests
        requests = Hash.new { |hash, key| hash[key] = [] }
        @selected.sort.each do |codename, names|
          names.each do |name|
            @catalog.package(name).os_dependencies_for(codename).gems.each do |entry|
              gem = Debian::Naming.gem_name(entry)
              requirement = ReleaseGems.requirement_of(entry, gem) || Gem::Requirement.default
              add(requests, gem, requirement, "#{name}'s osdep #{entry}")
            end
          end
        end
        requests
      end

      def add(requests, gem, requirement, who)
        requests[gem] << [requirement, who] unless requests[gem].any? { |known, by| known == requirement && by == who }
      end

      def walk(queue)
        while (name = queue.shift)
          next if @catalog.package?(name) # a workspace package of that name: ReleaseGems says so for gems:

          archive = @pinned.key?(name) ? pinned(name) : automatic(name)
          next unless archive

          @needs[name] = archive.runtime_dependencies.map(&:first)
          archive.runtime_dependencies.each do |dependency, requirement|
            add(@requests, dependency, requirement, "gem #{name} #{archive.version}")
            queue << dependency unless queue.include?(dependency)
          end
        end
      end

      def pinned(name)
        return nil if @chosen.key?(name)

        version = @pinned[name]
        # the same version as the planner sees it: 1.2 is not 1.2.0 there
        if !@blacklisted.call(name) && !@shadowed.key?(name) && everywhere?(name) { |found| found.to_s == version }
          @chosen[name] = :system
          return nil
        end
        @chosen[name] = version
        # a .gem that cannot be had is ReleaseGems' error, on its `gems:` entry
        archive = @fetch.call(name, version)
        check_pinned_ruby(archive)
        archive
      rescue GemArchive::Problem
        nil
      end

      # A version of `gems:` is never second-guessed: one whose Ruby a
      # target lacks is an error, unless that target's distribution has it
      # (the planner takes ruby-<gem> there, and nothing is built).
      def check_pinned_ruby(archive)
        requirement = archive.required_ruby
        refused = @rubies.refusing(requirement).reject do |codename, _|
          provided_on?(archive.name, codename) { |found| found.to_s == archive.version }
        end
        return if refused.empty?

        @problems << Diagnostic.error("gem-ruby", "gem #{archive.name} #{archive.version} of gems: needs Ruby #{requirement}, " \
                                                  "which #{TargetRubies.describe(refused)} is not: it would install there " \
                                                  "but not load", location: @locate.call(archive.name) || @location,
                                                                  hint: "pin a version of #{archive.name} for that Ruby")
      end

      # The gem chosen (again) for what is asked of it now, nil when the
      # distribution provides it or the earlier choice still fits.
      def automatic(name)
        requirements = @requests[name].map(&:first)
        fits = ->(version) { requirements.all? { |requirement| requirement.satisfied_by?(version) } }
        current = @chosen[name]
        return nil if current == :system && everywhere?(name, &fits)
        return nil if current && current != :system && fits.call(Gem::Version.new(current))

        if @archives.values.none? || (current.nil? && !@shadowed.key?(name) && everywhere?(name, &fits))
          @chosen[name] = :system
          return nil
        end
        archive = choose(name, fits)
        @chosen[name] = archive.version if archive
        archive
      end

      # The gems taken from the distributions that one of them has
      # depending on a gem packaged here are packaged here too; they may
      # shadow others in turn, so until none is left.
      def unshadow
        loop do
          found = shadowed
          break if found.empty?

          found.each do |name, shadowing|
            @shadowed[name] = shadowing
            @chosen.delete(name)
          end
          walk(found.keys)
        end
      end

      # name => ShadowedGems::Shadowing of the gems taken from the
      # distributions now that a target's archive has depending on one
      # packaged here (the first target by name that has).
      def shadowed
        packaged = @chosen.reject { |_, version| version == :system }
        return {} if packaged.empty?

        shadows = @depends.sort.map do |target, depends|
          ShadowedGems.new(depends: depends || {}, packaged: packaged, codename: target.split("/").first)
        end
        @chosen.select { |_, version| version == :system }.keys.sort.filter_map do |name|
          deb = Debian::Naming.distribution_gem(name)
          shadowing = shadows.lazy.filter_map { |shadow| shadow.of(deb) }.first
          shadowing && [name, shadowing]
        end.to_h
      end

      # Whether every target's archive was read and has ruby-<name> at a
      # version the block accepts.
      def everywhere?(name, &block)
        return false if @archives.empty?

        @archives.values.all? { |found| has?(found, name, &block) }
      end

      # Whether every archive of +codename+'s targets was read and has
      # ruby-<name> at a version the block accepts.
      def provided_on?(name, codename, &block)
        found = @archives.select { |target, _| target.split("/").first == codename }.values
        !found.empty? && found.all? { |archive| has?(archive, name, &block) }
      end

      def has?(archive, name)
        # any version the archive has (a real ruby-<gem> and libruby's Provides)
        Array(archive&.[](Debian::Naming.distribution_gem(name))).any? do |text|
          version = Debian::GemVersion.from_debian(text)
          version && yield(version)
        end
      end

      # The GemArchive of the version to package (GemCandidates), or nil
      # with the problem.
      def choose(name, fits)
        refused = []
        @spared.delete(name)
        found = @candidates.best(name, refused, &fits) || spare(name, fits)
        return found if found

        @problems << if refused.empty?
                       GemProblems.unresolvable(name, @requests[name], @versions, shadowing: @shadowed[name], location: @location)
                     else
                       GemProblems.ruby_refused(name, @requests[name], @versions, refused, @rubies, location: @location)
                     end
        nil
      rescue GemVersions::Problem => e
        @problems << Diagnostic.error("gem-source", e.message, location: @location, hint: "check gem_source")
        nil
      rescue GemArchive::Problem => e
        @problems << Diagnostic.error("gem-source", e.message, location: @location, hint: "check gem_source and the version")
        nil
      end

      # No version that fits runs on every target's Ruby: a target whose
      # distribution has ruby-<name> at a version that fits takes that (the
      # planner does; Plan::GemRubyCheck stops a plan that would build it
      # there after all), and the version is chosen for the others' Ruby.
      def spare(name, fits)
        # a blacklisted gem is never taken from a distribution
        return nil if @blacklisted.call(name)

        codenames = @rubies.rubies.keys.select { |codename| provided_on?(name, codename, &fits) }
        return nil if codenames.empty?

        found = @candidates.best(name, [], @rubies.without(codenames), &fits)
        @spared[name] = codenames if found
        found
      end

      # A cycle among the packaged gems, as one error: no order builds them.
      def check_cycles
        packaged = @chosen.reject { |_, version| version == :system }.keys
        edges = packaged.to_h { |name| [name, (@needs[name] || []) & packaged] }
        cycle = edges.keys.sort.lazy.filter_map { |name| cycle_from(name, edges, [name]) }.first
        return unless cycle

        @problems << Diagnostic.error("gem-cycle", "gems #{cycle.join(' → ')} need each other: no build order makes " \
                                                   "their packages", location: @location,
                                                                     hint: "take one of them from the distribution (its archive), or " \
                                                                           "package them by hand")
      end

      def cycle_from(name, edges, path)
        edges.fetch(name).sort.each do |next_name|
          return path + [next_name] if next_name == path.first
          next if path.include?(next_name)

          found = cycle_from(next_name, edges, path + [next_name])
          return found if found
        end
        nil
      end

      def notes
        shadowed = @shadowed.sort.map { |name, shadowing| "#{shadowing}: gem #{name} is packaged here" } +
                   @spared.sort.map do |name, codenames|
                     "no version of gem #{name} that fits runs on the Ruby of #{codenames.join(', ')}: taken from the " \
                       "distribution there, packaged at #{@chosen[name]} for the other targets"
                   end
        unchecked = @archives.select { |_, found| found.nil? }.keys.sort
        asked = @requests.keys - @pinned.keys - @chosen.reject { |_, version| version == :system }.keys
        return shadowed if unchecked.empty? || asked.empty?

        shadowed + ["gem osdeps are not checked on #{unchecked.join(', ')} (no distribution archive: " \
                    "distributions.<codename>.archive): #{asked.sort.join(', ')} taken as ruby-<gem> there"]
      end
    end
  end
end
