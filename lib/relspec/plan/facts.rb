# frozen_string_literal: true

module Relspec
  module Plan
    # Everything planning reads, read once by Plan.read, so that the
    # decisions (Plan.decide: Planner, Settlement, Versioning) work on values
    # alone and can be fed in memory:
    # +resolution+: the release's ReleaseSpec::Resolution;
    # +release_catalog+: Catalog::ReleaseCatalog; +ancestors+: [Ancestor] in
    # search order; +inventory+: Inventory (the ancestors' indices);
    # +distribution+: DistributionPackages (the targets' ruby-* packages);
    # +own+: OwnRepository (what the release's repository holds);
    # +previous+: the Lock read (nil: none, or discarded); +lock_path+: where
    # the lock is written; +project_root+: where specs/, releases/ and
    # overlays/ are; +overlays+: callable (package name, Target) →
    # Debian::Overlay; +uncommitted+: name => Catalog::UncommittedChanges::Change
    # for the selected checkouts with changes beyond their commit.
    Facts = Struct.new(:resolution, :release_catalog, :ancestors, :inventory, :distribution, :own, :previous,
                       :lock_path, :project_root, :overlays, :uncommitted, keyword_init: true)
  end
end
