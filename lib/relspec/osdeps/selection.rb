# frozen_string_literal: true

require_relative "../apt/dependency"

module Relspec
  module Osdeps
    # The user side of a release (rock-osdeps' deb_blacklist.yml): which
    # packages of the release stay usable when some are blacklisted. Every
    # blacklisted package is disabled, and so is every package that can no
    # longer satisfy a dependency: a dependency group is broken when all its
    # alternatives (and all providers of virtual names among them) are
    # disabled. Computed in memory from the Depends of the Packages indices.
    class Selection
      # +mapping+: autoproj package => Debian name (for the user's OS);
      # +indices+: Apt::PackageIndex list; +blacklist+: BlacklistFile entries.
      def initialize(mapping, indices, blacklist)
        @mapping = mapping
        @autoproj_of = mapping.each_with_object({}) { |(package, deb), out| out[deb] ||= package }
        @blacklist = blacklist
        index(indices)
        @disabled = {}
        @unmatched = []
        run
      end

      # autoproj package => Debian name, for what stays usable.
      def active
        @mapping.reject { |package, _| @disabled.key?(@mapping[package]) }.sort.to_h
      end

      # autoproj package => why it is off: the chain of steps from it to the
      # blacklist entry.
      def inactive
        @disabled.filter_map do |deb, reason|
          name = @autoproj_of[deb]
          name && [name, reason]
        end.sort.to_h
      end

      # Blacklist entries that matched no package of the release.
      attr_reader :unmatched

      private

      def index(indices)
        @groups = Hash.new { |hash, key| hash[key] = [] } # name => [[dependent, group], …]
        @providers = Hash.new { |hash, key| hash[key] = [] }
        @provides = Hash.new { |hash, key| hash[key] = [] }
        @present = {}
        indices.each do |index|
          index.entries.each_value do |entry|
            next if @present.key?(entry.name)

            @present[entry.name] = true
            Apt::Dependency.provided_names(entry.provides).each do |virtual|
              @providers[virtual] << entry.name
              @provides[entry.name] << virtual
            end
            Apt::Dependency.parse(entry.depends).each do |group|
              names = group.map(&:name).uniq
              names.each { |name| @groups[name] << [entry.name, names] }
            end
          end
        end
      end

      def run
        queue = []
        @blacklist.each do |entry|
          matches = @mapping.keys.select { |package| entry.pattern.match?(package) }
          @unmatched << entry if matches.empty?
          matches.sort.each do |package|
            deb = @mapping[package]
            next if @disabled.key?(deb)

            @disabled[deb] = ["blacklisted by #{entry.pattern.source.inspect} (#{entry.location})"]
            queue << deb
          end
        end
        propagate(queue)
      end

      def propagate(queue)
        until queue.empty?
          deb = queue.shift
          ([deb] + @provides[deb]).flat_map { |name| @groups[name] }.each do |dependent, names|
            next if @disabled.key?(dependent) || names.any? { |name| available?(name) }

            @disabled[dependent] = ["depends on #{label(deb)}", *@disabled[deb]]
            queue << dependent
          end
        end
      end

      # A name from outside the indices comes from elsewhere: assume it is there.
      def available?(name)
        return true if !@present.key?(name) && @providers[name].empty?

        (@present.key?(name) && !@disabled.key?(name)) || @providers[name].any? { |provider| !@disabled.key?(provider) }
      end

      def label(deb)
        @autoproj_of[deb] || deb
      end
    end
  end
end
