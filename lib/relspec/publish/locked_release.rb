# frozen_string_literal: true

require_relative "../project"
require_relative "../location"
require_relative "../diagnostic"
require_relative "../error"
require_relative "../apt/cache"
require_relative "../plan/lock"
require_relative "../plan/lock_parser"
require_relative "../plan/inventory"
require_relative "../target"

module Relspec
  module Publish
    # The facts publish lists a repository's osdeps from, read before the
    # repository is touched: the release's lock (releases/<r>/lock.yml, as
    # compile wrote it) and the ancestors' indices. The lock must be the one
    # of this spec and of these ancestors: a missing or stale lock is an
    # error naming it (run compile again), never a silent new plan.
    class LockedRelease
      HINT = "run relspec compile %s (and build) again, then publish"
      DAMAGED_HINT = "fix the file (it is in git), or run relspec compile %s --discard-lock (and build) again, then publish"

      attr_reader :lock, :inventory

      # +resolution+: the release's ReleaseSpec::Resolution; +spec_path+ as
      # the user gave it; +timeout+: HTTP seconds for remote ancestors.
      def self.read(resolution, spec_path, timeout:)
        effective = resolution.effective
        path = Project.of_spec(spec_path).lock_path(effective.release)
        lock = read_lock(path, effective.release, spec_path)
        stale!(path, spec_path, "#{effective.release} has no lock #{path} to list its repository from") unless lock
        stale!(path, spec_path, "#{path} was planned from another version of #{spec_path}") \
          unless lock.spec_digest == Plan::Lock.spec_digest(effective)
        ancestors = resolution.lineage.opened_ancestors(fetcher_options: { timeout: timeout },
                                                        cache: Apt::Cache.new(Apt::Cache.default_dir))
        inventory = Plan::Inventory.read(ancestors, Target.all(effective))
        moved = moved_ancestors(lock, inventory)
        stale!(path, spec_path, "#{path} is out of date: the repository of #{moved.join(', ')} holds other packages now") \
          unless moved.empty?
        new(lock, inventory)
      end

      # The lock parser's hint offers compile's --discard-lock; publish has
      # no such option, so its reader says where that option is.
      def self.read_lock(path, release, spec_path)
        Plan::LockParser.read(path, release: release)
      rescue LockError => e
        hint = format(DAMAGED_HINT, spec_path)
        raise LockError, (e.diagnostics.map do |found|
          Diagnostic.error(found.rule, found.message, location: found.location, hint: hint)
        end)
      end

      # "ancestor codename" of every ancestor whose content digest differs
      # from the one the lock recorded.
      def self.moved_ancestors(lock, inventory)
        recorded = lock.ancestors.flat_map { |name, digests| digests.map { |codename, digest| [[name, codename], digest] } }.to_h
        current = inventory.release_digests
        (recorded.keys | current.keys).sort.reject { |key| recorded[key] == current[key] }.map { |key| key.join(" on ") }
      end

      def self.stale!(path, spec_path, message)
        raise InvalidInput, [Diagnostic.error("publish-lock", message, location: Location.file_only(path),
                                                                       hint: format(HINT, spec_path))]
      end
      private_class_method :read_lock, :moved_ancestors, :stale!

      def initialize(lock, inventory)
        @lock = lock
        @inventory = inventory
        freeze
      end
    end
  end
end
