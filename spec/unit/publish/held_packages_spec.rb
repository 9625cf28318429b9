# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/held_packages"
require "relspec/plan/lock"
require "relspec/plan/history"
require "relspec/plan/inventory"
require "relspec/apt/package_index"

# Publish's listing fed in memory: a Lock and the repositories' indices as
# plain values (docs/publish.md, "The repository's osdeps files").
RSpec.describe Relspec::Publish::HeldPackages do
  let(:amd64) { Relspec::Target.new("bookworm", "amd64").freeze }
  let(:arm64) { Relspec::Target.new("bookworm", "arm64").freeze }

  def entry(decision, deb = nil, version = nil, from: nil)
    Relspec::Plan::Lock::Entry.new(decision: decision, deb: deb, version: version, from: from)
  end

  def lock(targets)
    Relspec::Plan::Lock.new(release: "child", spec_digest: "d" * 64, ancestors: {}, packages: {}, targets: targets,
                            history: Relspec::Plan::History.empty, warnings: [], notes: [])
  end

  def index(versions)
    Relspec::Apt::PackageIndex.new(versions.to_h do |name, version|
      [name, Relspec::Apt::PackageIndex::Entry.new(name, version, [], [], nil, "amd64")]
    end)
  end

  def own(by_target)
    Relspec::Plan::OwnRepository.new(by_target.transform_values { |versions| index(versions) })
  end

  def inventory(by_key)
    Relspec::Plan::Inventory.new(by_key.transform_values { |versions| index(versions) }, {})
  end

  let(:locked) do
    lock("bookworm/amd64" => {
           "base/cmake" => entry("inherit", "rock-base-base-cmake", "1.0-3~bookworm", from: "base"),
           "base/types" => entry("build", "rock-child-base-types", "2.0-1~bookworm"),
           "drivers/io" => entry("published", "rock-child-drivers-io", "1.0-2~bookworm"),
           "tools/gem" => entry("system", "ruby-gem", "0.5-1"),
           "tools/gone" => entry("unavailable")
         })
  end

  def list(own: self.own({}), inventory: self.inventory({}), lock: locked)
    described_class.list(lock, own: own, inventory: inventory)
  end

  it "lists a build and a published package when the release's repository holds them at the locked version" do
    listing = list(own: own(amd64 => { "rock-child-base-types" => "2.0-1~bookworm", "rock-child-drivers-io" => "1.0-2~bookworm" }))
    decisions = listing.targets.fetch(amd64)
    expect(decisions.fetch("base/types").deb_name).to eq("rock-child-base-types")
    expect(decisions.fetch("base/types")).to be_build
    expect(decisions.fetch("drivers/io")).to be_published
    expect(listing.missing).to include("bookworm/amd64 base/cmake (rock-base-base-cmake 1.0-3~bookworm)")
    expect(listing.missing).not_to include(a_string_including("base/types"))
  end

  it "leaves out a build the repository holds at another version (a failed build of a new revision), naming it" do
    listing = list(own: own(amd64 => { "rock-child-base-types" => "2.0-0~bookworm" }))
    expect(listing.targets.fetch(amd64)).not_to include("base/types", "drivers/io")
    expect(listing.missing).to include("bookworm/amd64 base/types (rock-child-base-types 2.0-1~bookworm)",
                                       "bookworm/amd64 drivers/io (rock-child-drivers-io 1.0-2~bookworm)")
  end

  it "compares versions by dpkg's rules, not as text" do
    listing = list(own: own(amd64 => { "rock-child-base-types" => "2.0-01~bookworm" }))
    expect(listing.targets.fetch(amd64)).to include("base/types")
  end

  it "lists an inherited package only when the ancestor it came from holds it at that version" do
    held = list(inventory: inventory(["base", amd64] => { "rock-base-base-cmake" => "1.0-3~bookworm" }))
    expect(held.targets.fetch(amd64).fetch("base/cmake").ancestor).to eq("base")
    other = list(inventory: inventory(["other", amd64] => { "rock-base-base-cmake" => "1.0-3~bookworm" }))
    expect(other.targets.fetch(amd64)).not_to include("base/cmake")
    older = list(inventory: inventory(["base", amd64] => { "rock-base-base-cmake" => "1.0-2~bookworm" }))
    expect(older.targets.fetch(amd64)).not_to include("base/cmake")
  end

  it "lists a distribution's gem as locked and never an unavailable package" do
    decisions = list.targets.fetch(amd64)
    expect(decisions.fetch("tools/gem").deb_name).to eq("ruby-gem")
    expect(decisions).not_to include("tools/gone")
    expect(list.missing).not_to include(a_string_including("tools/gone"), a_string_including("tools/gem"))
  end

  it "reads each target's own holdings: a package held on amd64 is not thereby held on arm64" do
    entries = { "base/types" => entry("build", "rock-child-base-types", "2.0-1~bookworm") }
    listing = list(lock: lock("bookworm/arm64" => entries, "bookworm/amd64" => entries),
                   own: own(amd64 => { "rock-child-base-types" => "2.0-1~bookworm" }))
    expect(listing.targets.keys).to eq([amd64, arm64])
    expect(listing.targets.fetch(amd64)).to include("base/types")
    expect(listing.targets.fetch(arm64)).to be_empty
    expect(listing.missing).to eq(["bookworm/arm64 base/types (rock-child-base-types 2.0-1~bookworm)"])
  end
end
