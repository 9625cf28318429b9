# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan"

# Settlement fed in memory: a catalog, decisions as the Planner gives them,
# the lock's history and the repository's index as values, overlays as a
# function; no workspace, repository or child process (docs/plan.md,
# "Versions").
RSpec.describe Relspec::Plan::Settlement do
  let(:target) { Relspec::Plan::Target.new("bookworm", "amd64").freeze }
  let(:upstream) { "1.0.20200601.000000" }
  let(:graph) { { "base/cmake" => [], "base/logging" => ["base/cmake"], "base/types" => ["base/logging"] } }
  # the package set's import patches, per package
  let(:patches) { {} }
  # the packages imported from an archive (`type: archive`)
  let(:archives) { [] }
  # made on every call: an example may change the patches between settlements
  def catalog
    packages = graph.to_h do |name, dependencies|
      [name, Relspec::Catalog::Package.new(
        name: name, package_set: "set", build_type: "cmake", commit_time: "2020-06-01T00:00:00Z", source_dir: "src/#{name}",
        version: "1.0", dependencies: dependencies, patches: patches.fetch(name, []),
        vcs: if archives.include?(name)
               Relspec::Catalog::Vcs.new(type: "archive", url: "https://example.org/#{name}.tar.gz", sha256: "e" * 64)
             else
               Relspec::Catalog::Vcs.new(type: "git", url: "https://example.org/#{name}.git", commit: "c" * 40)
             end
      )]
    end
    Relspec::Catalog.new(packages: packages, layout: graph.keys, codenames: ["bookworm"])
  end
  let(:effective) do
    Relspec::ReleaseSpec::EffectiveSpec.new({ "release" => "r", "targets" => { "bookworm" => ["amd64"] },
                                              "install_prefix" => "/opt/rock", "maintainer" => "M <m@example.org>" }, {})
  end
  # an overlay that adds nothing (a package without overlays/<name>/)
  let(:no_overlay) { Struct.new(:signature).new("") }

  def deb(name, release = "r") = "rock-#{release}-#{name.tr('/', '-')}"

  # base/cmake inherited from ancestor p, the others to build.
  def decisions
    graph.keys.to_h do |name|
      [name, if name == "base/cmake"
               Relspec::Plan::Decision.new(package: name, kind: :inherit, deb_name: deb(name, "p"),
                                           version: "#{upstream}-4~bookworm", ancestor: "p").freeze
             else
               Relspec::Plan::Decision.new(package: name, kind: :build, deb_name: deb(name),
                                           cause: Relspec::Plan::Cause.missing).freeze
             end]
    end
  end

  def settle(history: Relspec::Plan::History.empty, held: {}, overlays: ->(_name, _arch) { no_overlay })
    release_catalog = Relspec::Catalog::ReleaseCatalog.new(catalog, { "bookworm" => graph.keys }, { "bookworm" => {} },
                                                           "/workspace", {})
    prefixes = Relspec::ReleaseSpec::Prefixes.new(install_prefix: "/opt/rock", separate_prefixes: true, package_prefix: "rock")
    ancestor = Relspec::ReleaseSpec::Lineage::Opened.new(Relspec::ReleaseSpec::Lineage::Member.new(name: "p", prefixes: prefixes), nil)
    inputs = Relspec::Plan::DebianInputs.new(effective: effective, ancestors: [ancestor], release_catalog: release_catalog)
    index = held.transform_values { |version| Struct.new(:version).new(version) }
    own = Relspec::Plan::OwnRepository.new(held.empty? ? {} : { target => index })
    versioning = Relspec::Plan::Versioning.new(history: history, own: own)
    rising = Relspec::Plan::RisingUpstream.new(history: history, own: own)
    described_class.new(catalog: catalog, inputs: inputs, versioning: versioning, overlays: overlays, rising: rising)
                   .call(target => decisions)
  end

  it "versions the builds dependencies first and names the dependencies' settled versions in debian/" do
    targets, work = settle
    settled = targets.fetch(target)
    expect(settled.fetch("base/cmake").kind).to eq(:inherit)
    expect(settled.fetch("base/logging").version.to_s).to eq("#{upstream}-1~bookworm")
    expect(settled.fetch("base/types").depends).to eq(["base/logging"])
    input = work.fetch(target).fetch("base/types").input
    expect(input.dependencies.map(&:to_h))
      .to eq([{ deb_name: deb("base/logging"), version: "#{upstream}-1~bookworm", install_dir: "/opt/rock/r/#{deb('base/logging')}" }])
    # an inherited dependency installs into its ancestor's prefix
    expect(work.fetch(target).fetch("base/logging").input.dependencies.map(&:install_dir))
      .to eq(["/opt/rock/p/#{deb('base/cmake', 'p')}"])
  end

  it "records the digest of debian/ each version was settled from, and gives the same digests twice" do
    first, = settle
    second, = settle
    digests = first.fetch(target).values.filter_map(&:debian_digest)
    expect(digests.size).to eq(2)
    expect(digests).to all(match(/\A[0-9a-f]{64}\z/))
    expect(second.fetch(target).values.filter_map(&:debian_digest)).to eq(digests)
  end

  it "moves the revision of a dependent when a dependency's revision moves" do
    first, = settle
    logging = first.fetch(target).fetch("base/logging")
    types = first.fetch(target).fetch("base/types")
    # the history knows both at revision 1, but base/logging's repository copy is
    # revision 1 without the history vouching for its debian/: it goes to 2
    history = Relspec::Plan::History.empty.with_all(
      [[target, "base/logging", logging.version, "0" * 64], [target, "base/types", types.version, types.debian_digest]]
    )
    again, = settle(history: history)
    expect(again.fetch(target).fetch("base/logging").version.revision).to eq(2)
    # base/types' debian/control now names base/logging's revision 2
    expect(again.fetch(target).fetch("base/types").version.revision).to eq(2)
  end

  it "says published when the history vouches for the version and the repository holds it" do
    first, = settle
    history = Relspec::Plan::History.empty.with_all(first.fetch(target).values.select(&:build?).map do |decision|
      [target, decision.package, decision.version, decision.debian_digest]
    end)
    held = first.fetch(target).values.select(&:build?).to_h { |decision| [decision.deb_name, decision.version.to_s] }
    again, = settle(history: history, held: held)
    expect(again.fetch(target).values.map(&:kind)).to eq(%i[inherit published published])
  end

  context "with every build published and base/logging changed (the early cutoff's candidates)" do
    def published
      first, = settle
      builds = first.fetch(target).values.select(&:build?)
      history = Relspec::Plan::History.empty.with_all(builds.map do |decision|
        [target, decision.package, decision.version, decision.debian_digest]
      end)
      [history, builds.to_h { |decision| [decision.deb_name, decision.version.to_s] }]
    end

    def changed(names)
      ->(name, _arch) { Struct.new(:signature).new(names.include?(name) ? "patch" : "") }
    end

    it "names the dependent a candidate that keeps its published version when only base/logging's version moved it" do
      history, held = published
      again, = settle(history: history, held: held, overlays: changed(["base/logging"]))
      logging = again.fetch(target).fetch("base/logging")
      types = again.fetch(target).fetch("base/types")
      expect([logging.kind, logging.version.revision, logging.cutoff]).to eq([:build, 2, nil])
      expect([types.kind, types.version.revision]).to eq([:build, 2]) # built as today until the cutoff decides
      # no dependency of base/types is a candidate: kept, its debian/ is the one planned
      expect(types.cutoff.to_h).to eq(keeps: Relspec::Debian::PackageVersion.parse("#{upstream}-1~bookworm"),
                                      because: ["base/logging"], debian_digest: types.debian_digest,
                                      against: { deb("base/logging") => "#{upstream}-1~bookworm" })
      expect(types.cutoff.to_s).to eq("early cutoff candidate: #{upstream}-1~bookworm stays if the interface of " \
                                      "base/logging does not change")
    end

    context "with a dependent of the candidate" do
      let(:graph) { super().merge("base/app" => ["base/types"]) }

      # Issue 45: the versions the candidate's kept build was made against,
      # which its closure's new builds must be compared with; base/cmake is
      # inherited, not built here.
      it "names what the kept build was made against: the published version of each build of the closure" do
        history, held = published
        again, = settle(history: history, held: held, overlays: changed(["base/logging"]))
        app = again.fetch(target).fetch("base/app")
        expect(%w[base/logging base/types base/app].map { |name| again.fetch(target).fetch(name).version.revision }).to eq([2, 2, 2])
        expect(app.cutoff.because).to eq(["base/types"])
        # base/logging through base/types: the published versions, not the ones built now
        expect(app.cutoff.against).to eq(deb("base/logging") => "#{upstream}-1~bookworm", deb("base/types") => "#{upstream}-1~bookworm")
        expect(app.cutoff.against).to be_frozen
        # a build the repository does not hold is no baseline: not named
        partly, = settle(history: history, held: held.except(deb("base/logging")), overlays: changed(["base/logging"]))
        expect(partly.fetch(target).fetch("base/app").cutoff.against).to eq(deb("base/types") => "#{upstream}-1~bookworm")
      end
    end

    it "names no candidate when the dependent's own debian/ changed too, or nothing it keeps is published" do
      history, held = published
      both, = settle(history: history, held: held, overlays: changed(%w[base/logging base/types]))
      expect(both.fetch(target).fetch("base/types").cutoff).to be_nil
      unpublished, = settle(history: history, held: held.except(deb("base/types")), overlays: changed(["base/logging"]))
      expect(unpublished.fetch(target).fetch("base/types").cutoff).to be_nil
    end
  end

  it "takes the overlay into the digest" do
    plain, = settle
    patched, = settle(overlays: ->(name, _arch) { Struct.new(:signature).new(name == "base/types" ? "patch" : "") })
    expect(patched.fetch(target).fetch("base/types").debian_digest)
      .not_to eq(plain.fetch(target).fetch("base/types").debian_digest)
    expect(patched.fetch(target).fetch("base/logging").debian_digest).to eq(plain.fetch(target).fetch("base/logging").debian_digest)
  end

  context "with a package set patch of base/types" do
    def patch(content)
      Relspec::Catalog::ImportPatch.new(path: "set/patches/fix.patch", level: 0, content: content).freeze
    end

    let(:patches) { { "base/types" => [patch("--- x\n+++ x\n@@ -1 +1 @@\n-a\n+b\n")] } }

    it "takes the patch into the digest, so that changing it gives a new revision" do
      first, = settle
      types = first.fetch(target).fetch("base/types")
      history = Relspec::Plan::History.empty.with_all(first.fetch(target).values.select(&:build?).map do |decision|
        [target, decision.package, decision.version, decision.debian_digest]
      end)
      # the same patch: the same revision
      same, = settle(history: history)
      expect(same.fetch(target).fetch("base/types").version).to eq(types.version)
      patches["base/types"] = [patch("--- x\n+++ x\n@@ -1 +1 @@\n-a\n+c\n")]
      changed, = settle(history: history)
      expect(changed.fetch(target).fetch("base/types").version.revision).to eq(types.version.revision + 1)
      expect(changed.fetch(target).fetch("base/logging").version).to eq(first.fetch(target).fetch("base/logging").version)
    end
  end

  context "with an archive import whose time moved back (issue 46, case 13)" do
    let(:archives) { ["base/logging"] }

    it "raises its version above the one the history records, hands the raise on, and raises a git package's as well" do
      later = "1.0.20990101.000000"
      history = Relspec::Plan::History.empty
                                      .with(target, "base/logging", Relspec::Debian::PackageVersion.new(later, 2, "bookworm"), "d")
                                      .with(target, "base/types", Relspec::Debian::PackageVersion.new(later, 1, "bookworm"), "d")
      targets, work, raised = settle(history: history)
      expect(targets.fetch(target).fetch("base/logging").version.to_s).to eq("#{later}+really#{upstream}-1~bookworm")
      expect(work.fetch(target).fetch("base/types").input.dependencies.map(&:version))
        .to eq(["#{later}+really#{upstream}-1~bookworm"])
      # a git package moved to an older commit: reprepro would skip its lower version
      expect(targets.fetch(target).fetch("base/types").version.to_s).to eq("#{later}+really#{upstream}-1~bookworm")
      expect(raised.map(&:to_h)).to eq([{ package: "base/logging", target: target, given: upstream, above: later,
                                          upstream: "#{later}+really#{upstream}", import: true },
                                        { package: "base/types", target: target, given: upstream, above: later,
                                          upstream: "#{later}+really#{upstream}", import: false }])
    end
  end
end
