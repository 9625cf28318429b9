# frozen_string_literal: true

require_relative "lock_generator"

module Relspec
  module Plan
    # What one planning run hands on (plan, why, check, osdeps, compile,
    # publish): the decisions (+plan+, a ReleasePlan with settled versions),
    # the +lock+ of this plan and where it is written (+lock_path+), and the
    # few facts of what was read that the next stages need, each behind a
    # method that says what it is for. Immutable.
    class Result
      attr_reader :plan, :lock, :lock_path, :project_root

      # +resolution+: the release's ReleaseSpec::Resolution;
      # +release_catalog+: Catalog::ReleaseCatalog; +work+: Target =>
      # {package => Settlement::Work} for the builds (what compile emits);
      # +lock_read+: whether the plan started from the lock's history;
      # +project_root+: where specs/, releases/ and overlays/ are (Project).
      def initialize(resolution:, release_catalog:, plan:, lock:, lock_path:, work:, lock_read:, project_root:)
        @resolution = resolution
        @release_catalog = release_catalog
        @plan = plan
        @lock = lock
        @lock_path = lock_path
        @work = work
        @lock_read = lock_read
        @project_root = project_root
        freeze
      end

      # False when there was no lock, or it was discarded (--discard-lock).
      def lock_read?
        @lock_read
      end

      # The release's EffectiveSpec.
      def effective
        @resolution.effective
      end

      # Where +path+ (keys) is written in the release's spec, for diagnostics.
      def spec_location(path)
        @resolution.spec_file.location(path)
      end

      # The folder of the release's spec (relative paths of the spec start there).
      def spec_dir
        File.dirname(@resolution.spec_file.path)
      end

      # The Catalog the plan decided over.
      def catalog
        @release_catalog.catalog
      end

      # The workspace (or catalog snapshot) the catalog was read from.
      def workspace
        @release_catalog.workspace
      end

      # The names of the gems the release packages itself.
      def release_gem_names
        @release_catalog.gems.keys
      end

      # What compile needs to emit the build of +package+ on +target+.
      def work_for(target, package)
        @work.fetch(target).fetch(package)
      end

      def lock_text
        LockGenerator.dump(lock)
      end

      # True if the file changed.
      def write_lock
        LockGenerator.write(lock_path, lock)
      end
    end
  end
end
