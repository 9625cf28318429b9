# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/diff"

# A new Debian revision of an unchanged source must say what moved. The
# decisions are written here as a lock holds them (the diff only reads
# locks); diff_spec.rb shows the same on a real release hierarchy.
RSpec.describe Relspec::Diff::RevisionCause do
  def built(version, *causes, depends: nil)
    Relspec::Diff::Decision.new(kind: "build", deb: "rock-x", version: version, from: nil, causes: causes,
                                depends: depends).freeze
  end

  def compare(old, new)
    Relspec::Diff::TargetDiff.compare("bionic/amd64", old, new).changes.to_h { |change| [change.package, change] }
  end

  let(:blacklisted) { 'blacklisted by "base/types" (own build)' }

  it "names the dependency on the cause chain that changed version" do
    changes = compare({ "base/types" => built("2.0.1-1~bionic", blacklisted),
                        "drivers/io" => built("1.0.5-1~bionic", "depends on base/types", blacklisted) },
                      { "base/types" => built("2.0.2-1~bionic", blacklisted),
                        "drivers/io" => built("1.0.5-2~bionic", "depends on base/types", blacklisted) })
    expect(changes["drivers/io"].rebuilt_because).to eq("base/types changed version (2.0.1-1~bionic → 2.0.2-1~bionic)")
    expect(changes["base/types"].rebuilt_because).to be_nil # its own source moved
    expect(Relspec::Diff::Wording.causes(changes["drivers/io"]))
      .to eq("rebuilt with the same source because base/types changed version (2.0.1-1~bionic → 2.0.2-1~bionic); " \
             "built because depends on base/types ← #{blacklisted}")
    expect(changes["drivers/io"].to_h["rebuilt_because"]).to start_with("base/types changed version")
  end

  it "names the nearest dependency that changed, not the root of the chain when the root did not move" do
    chain = ["depends on base/logging", "depends on base/types", blacklisted]
    changes = compare({ "base/types" => built("2.0.1-1~bionic", blacklisted),
                        "base/logging" => built("1.1-1~bionic", "depends on base/types", blacklisted),
                        "tools/x" => built("0.9-1~bionic", *chain) },
                      { "base/types" => built("2.0.1-1~bionic", blacklisted),
                        "base/logging" => built("1.2-1~bionic", "depends on base/types", blacklisted),
                        "tools/x" => built("0.9-2~bionic", *chain) })
    expect(changes["tools/x"].rebuilt_because).to eq("base/logging changed version (1.1-1~bionic → 1.2-1~bionic)")
  end

  it "says the Debian inputs changed when no dependency on the chain moved, naming the target's other changes as candidates" do
    changes = compare({ "tools/x" => built("0.9-1~bionic", blacklisted) }, { "tools/x" => built("0.9-2~bionic", blacklisted) })
    expect(changes["tools/x"].rebuilt_because)
      .to eq("its Debian inputs changed (a dependency, the release's settings or the packaging)")

    others = %w[a b c d].to_h { |name| [name, built("1-1~bionic")] }
    # "same": only its cause changed; "bumped": a revision bump itself (a
    # consequence, not a candidate).
    changes = compare(others.merge("tools/x" => built("0.9-1~bionic", blacklisted), "same" => built("5-1~bionic"),
                                   "bumped" => built("7-1~bionic")),
                      others.transform_values { built("2-1~bionic") }
                            .merge("tools/x" => built("0.9-2~bionic", blacklisted), "same" => built("5-1~bionic", "moved"),
                                   "bumped" => built("7-2~bionic")))
    expect(changes["tools/x"].rebuilt_because)
      .to eq("its Debian inputs changed (a dependency, the release's settings or the packaging; " \
             "changed on this target and maybe among its dependencies: a, b, c, 1 more)")
  end

  # Locks record each build's dependencies (depends:): every dependency
  # that moved is named, also those off the cause chain, and other changes
  # of the target are not offered as candidates.
  it "names every recorded dependency that changed, on the cause chain or not" do
    inherited = ->(version) { Relspec::Diff::Decision.new(kind: "inherit", deb: "rock-b-cmake", version: version, from: "b", causes: []).freeze }
    old = { "base/cmake" => inherited.call("1.0-1~bionic"), "base/types" => built("2.0.1-1~bionic", blacklisted),
            "other" => built("5-1~bionic"),
            "drivers/io" => built("1.0.5-1~bionic", "depends on base/types", blacklisted, depends: %w[base/cmake base/types]) }
    new = { "base/cmake" => inherited.call("1.1-1~bionic"), "base/types" => built("2.0.2-1~bionic", blacklisted),
            "other" => built("6-1~bionic"),
            "drivers/io" => built("1.0.5-2~bionic", "depends on base/types", blacklisted, depends: %w[base/cmake base/types]) }
    expect(compare(old, new)["drivers/io"].rebuilt_because)
      .to eq("base/cmake changed version (1.0-1~bionic → 1.1-1~bionic); " \
             "base/types changed version (2.0.1-1~bionic → 2.0.2-1~bionic)")
  end

  it "says no dependency moved when the lock records them and none changed" do
    changes = compare({ "other" => built("5-1~bionic"), "base/types" => built("2-1~bionic"),
                        "tools/x" => built("0.9-1~bionic", blacklisted, depends: ["base/types"]) },
                      { "other" => built("6-1~bionic"), "base/types" => built("2-1~bionic"),
                        "tools/x" => built("0.9-2~bionic", blacklisted, depends: ["base/types"]) })
    expect(changes["tools/x"].rebuilt_because)
      .to eq("its Debian inputs changed (the release's settings, the packaging or where a direct dependency is " \
             "installed; none of its direct dependencies changed)")
  end

  it "does not take a dependency whose cause chain alone changed for what moved the revision" do
    changes = compare({ "base/types" => built("2-1~bionic", "pinned"),
                        "tools/x" => built("0.9-1~bionic", blacklisted, depends: ["base/types"]) },
                      { "base/types" => built("2-1~bionic", "blacklisted"),
                        "tools/x" => built("0.9-2~bionic", blacklisted, depends: ["base/types"]) })
    expect(changes["base/types"].kind).to eq("cause")
    expect(changes["tools/x"].rebuilt_because).to start_with("its Debian inputs changed (the release's settings")
  end

  it "names dependencies the build gained or lost" do
    changes = compare({ "base/cmake" => built("1-1~bionic"),
                        "tools/x" => built("0.9-1~bionic", blacklisted, depends: ["base/cmake"]) },
                      { "base/logging" => built("1-1~bionic"),
                        "tools/x" => built("0.9-2~bionic", blacklisted, depends: ["base/logging"]) })
    expect(changes["tools/x"].rebuilt_because)
      .to eq("base/logging changed (added); its dependencies changed (now also base/logging; no longer base/cmake)")
  end

  it "leaves new sources and inherited packages to the commit range and the ancestor" do
    inherited = ->(version) { Relspec::Diff::Decision.new(kind: "inherit", deb: "rock-b-x", version: version, from: "base", causes: []).freeze }
    changes = compare({ "a" => built("1.0-1~bionic"), "b" => inherited.call("1.0-1~bionic") },
                      { "a" => built("1.1-1~bionic"), "b" => inherited.call("1.0-2~bionic") })
    expect(changes.values.map(&:rebuilt_because)).to eq([nil, nil])
  end

  it "groups such rebuilds under what moved in the release's summary" do
    old = { "base/types" => built("2.0.1-1~bionic", blacklisted),
            "drivers/io" => built("1.0.5-1~bionic", "depends on base/types", blacklisted),
            "tools/y" => built("3.0-1~bionic", "depends on base/types", blacklisted) }
    new = { "base/types" => built("2.0.2-1~bionic", blacklisted),
            "drivers/io" => built("1.0.5-2~bionic", "depends on base/types", blacklisted),
            "tools/y" => built("3.0-2~bionic", "depends on base/types", blacklisted) }
    snapshot = ->(targets) { Relspec::Diff::Snapshot.new(release: "r", source: "x", spec_digest: nil, ancestors: {}, packages: {}, targets: targets, spec: nil) }
    diff = Relspec::Diff::ReleaseDiff.compare(snapshot.call("bionic/amd64" => old), snapshot.call("bionic/amd64" => new))
    expect(diff.cause_groups).to eq([["base/types changed version (2.0.1-1~bionic → 2.0.2-1~bionic)",
                                      [["bionic/amd64", "drivers/io"], ["bionic/amd64", "tools/y"]]],
                                     ["base/types is #{blacklisted}", [["bionic/amd64", "base/types"]]]])
    expect(Relspec::Diff.render([diff], "markdown"))
      .to include("- 2 rebuilt because base/types changed version (2.0.1-1~bionic → 2.0.2-1~bionic): `drivers/io`, `tools/y` (bionic/amd64)")
  end
end
