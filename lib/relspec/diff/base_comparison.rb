# frozen_string_literal: true

require_relative "git_tree"
require_relative "input"
require_relative "lock_view"
require_relative "snapshot"
require_relative "source_change"

module Relspec
  module Diff
    # `relspec diff --base REF`: every release of specs/ (or the specs
    # named) as committed at REF against the working tree. Specs and locks
    # at REF are read with git (GitTree); the working tree side is the spec
    # file and releases/<r>/lock.yml as they are now. A spec git sees
    # renamed is compared with its old release; a deleted spec shows its
    # release as removed, a new one as added. A new spec of the working
    # tree without a lock yet is planned (+planner+: spec path => Plan::Lock),
    # and so is one whose lock is out of date (Snapshot#stale says so).
    class BaseComparison
      SPECS = "specs"
      RELEASES = "releases"

      # +root+: the project folder (holding specs/ and releases/).
      def initialize(root, ref, planner:)
        @root = root
        @planner = planner
        @tree = GitTree.new(root, ref)
      end

      # [[old Snapshot, new Snapshot]] sorted by release; +names+: only these
      # releases (nil: all, including deleted specs).
      def pairs(names = nil)
        before = @tree.files(SPECS).select { |file| file.end_with?(".yml") }.map { |file| file.delete_suffix(".yml") }
        after = Dir.glob("*.yml", base: File.join(@root, SPECS)).map { |file| file.delete_suffix(".yml") }
        renamed = @tree.renames(SPECS).to_h { |old, new| [release_of(new), release_of(old)] }
        wanted = names || after
        pairs = wanted.sort.map do |name|
          old_name = renamed[name] || name
          known = before.include?(old_name)
          [old_side(known ? old_name : nil, name), new_side(name, plan: !known)]
        end
        return pairs if names

        gone = before - after - renamed.values
        pairs + gone.sort.map { |name| [old_side(name, name), Snapshot.empty(name, "(deleted)")] }
      end

      private

      # A working tree path as the user would write it.
      def shown(path)
        @root == "." ? path : File.join(@root, path)
      end

      def release_of(path)
        File.basename(path, ".yml")
      end

      def old_side(name, fallback)
        return Snapshot.empty(fallback, @tree.describe("#{SPECS}/#{fallback}.yml")) unless name

        lock_path = "#{RELEASES}/#{name}/lock.yml"
        text = @tree.read(lock_path)
        spec_path = "#{SPECS}/#{name}.yml"
        snapshot = text ? LockView.parse(text, source: @tree.describe(lock_path)) : Snapshot.empty(name, @tree.describe(spec_path))
        spec = @tree.read(spec_path)
        spec ? snapshot.with_spec(Input.spec_data(spec, @tree.describe(spec_path))) : snapshot
      end

      # +plan+: plan the spec when it has no lock (a new spec); a spec that
      # had no lock at the ref either is compared by its spec alone.
      def new_side(name, plan:)
        lock_path = "#{RELEASES}/#{name}/lock.yml"
        spec_path = "#{SPECS}/#{name}.yml"
        full_lock = File.join(@root, lock_path)
        full_spec = File.join(@root, spec_path)
        raise Error, "#{shown(spec_path)} does not exist" unless File.file?(full_spec)

        snapshot = if File.file?(full_lock)
                     current_or_planned(full_spec, full_lock, lock_path, spec_path)
                   elsif plan
                     LockView.snapshot(@planner.call(full_spec), source: shown(spec_path))
                   else
                     Snapshot.empty(name, shown(spec_path))
                   end
        snapshot.with_spec(Input.spec_data(Input.text_of(full_spec), shown(spec_path)), spec_dir: File.dirname(full_spec))
      end

      # The working tree's lock when it is what a plan writes now; else the
      # plan itself, marked as planned (a lock left behind by a spec edited
      # without `plan --write`, a moved pin or a republished ancestor would
      # make the diff say less than the truth).
      def current_or_planned(full_spec, full_lock, lock_path, spec_path)
        text = Input.text_of(full_lock)
        read = LockView.parse(text, source: shown(lock_path))
        lock = @planner.call(full_spec)
        return read if Plan::LockGenerator.dump(lock) == text

        planned = LockView.snapshot(lock, source: shown(spec_path))
        edited = (planned.packages.keys & read.packages.keys).sort.filter_map do |package|
          SourceChange.of(package, planned.packages[package], read.packages[package], decided: false, recorded_in: shown(lock_path))
        end
        Snapshot.new(**planned.to_h, stale: shown(lock_path), edited: edited.freeze).freeze
      end
    end
  end
end
