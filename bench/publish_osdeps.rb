# frozen_string_literal: true

# bench/publish_osdeps: how publish lists what a repository holds (its
# osdeps files), now — the release's lock checked against the spec and the
# ancestors' indices, the repository's indices read back, the locked
# decisions they hold (Publish::LockedRelease, Publish::HeldPackages) —
# against its peer, what publish did before: a whole new plan (workspace
# load, indices, decisions; Plan.run) filtered to what is not a build.
# Both render the files in memory and must agree byte for byte (the bench
# stops otherwise). Run from a project root after bin/demo:
#
#   bundle exec ruby bench/publish_osdeps.rb [SPEC] [RUNS]
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/plan"
require "relspec/publish"
require "relspec/osdeps/repository_presence"

SPEC = ARGV.fetch(0, "specs/demo-child.yml")
RUNS = Integer(ARGV.fetch(1, "5"))

resolution = Relspec::ReleaseSpec.resolve(SPEC)
effective = resolution.effective
repository = effective.repository.path
distributions = effective.distributions

from_lock = lambda do
  locked = Relspec::Publish::LockedRelease.read(resolution, SPEC, timeout: 10)
  reader = Relspec::Apt::Opening.repository(effective.repository, repository)
  own = Relspec::Plan::OwnRepository.read(reader, Relspec::Target.all(effective))
  listing = Relspec::Publish::HeldPackages.list(locked.lock, own: own, inventory: locked.inventory)
  Relspec::Osdeps::Renderer.render(listing.targets, distributions)
end
from_plan = lambda do
  planned = Relspec::Plan.run(SPEC)
  present = Relspec::Osdeps::RepositoryPresence.new.to_proc
  Relspec::Osdeps::Renderer.render(planned.plan.targets, distributions, present: present)
end

raise "the two listings differ: #{from_lock.call.inspect} vs #{from_plan.call.inspect}" unless from_lock.call == from_plan.call

now = Timing.median(RUNS) { from_lock.call }
peer = Timing.median(RUNS) { from_plan.call }
puts format("%s: the repository's osdeps files, in process (median of %d)", effective.release, RUNS)
puts format("lock + indices (publish now)            %.3f s", now)
puts format("peer: a new plan (publish before)       %.3f s", peer)
puts format("ratio peer / now                        %.0f×", peer / now)
