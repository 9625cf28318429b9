# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "relspec/report/reading"
require "relspec/target_build"
require "relspec/builder/build_plan"
require "relspec/builder/build_results"
require "relspec/plan/lock"
require "relspec/target"

# The page's data from files as relspec writes them (plan.yml and
# build-results.yml parsed from text, the lock as its parser returns it,
# logs on disk): a failed build, two builds it blocks, an inherited
# package, one not built yet.
RSpec.describe Relspec::Report::Reading do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:blacklisted) { 'blacklisted by "base/types" (own API)' }

  def lock(release, entries)
    Relspec::Plan::Lock.new(release: release, spec_digest: "d", ancestors: {}, packages: {},
                            targets: { "bookworm/amd64" => entries }, history: Relspec::Plan::History.empty,
                            warnings: [], notes: [])
  end

  def entry(decision, version, from: nil, causes: nil)
    Relspec::Plan::Lock::Entry.new(decision: decision, deb: "rock-x", version: version, from: from, causes: causes)
  end

  let(:child_lock) do
    lock("child", "base/cmake" => entry("inherit", "1.0-1", from: "base"),
                  "base/types" => entry("build", "2.0-1", causes: [blacklisted]),
                  "drivers/io" => entry("build", "1.0-1", causes: ["depends on base/types", blacklisted]),
                  "tools/ui" => entry("build", "0.1-1", causes: ["depends on drivers/io", "depends on base/types", blacklisted]),
                  "tools/new" => entry("build", "0.2-1", causes: ["missing in all ancestors"]))
  end

  let(:plan) do
    Relspec::Builder::BuildPlan.parse(<<~YAML, dir: @dir)
      release: child
      target: bookworm/amd64
      builds:
        - { package: base/types, source: rock-types, version: 2.0-1, dsc: a.dsc, build_depends: [] }
        - { package: drivers/io, source: rock-io, version: 1.0-1, dsc: b.dsc, build_depends: [rock-types] }
        - { package: tools/ui, source: rock-ui, version: 0.1-1, dsc: c.dsc, build_depends: [rock-io] }
        - { package: tools/new, source: rock-new, version: 0.2-1, dsc: d.dsc, build_depends: [] }
    YAML
  end

  let(:results) do
    Relspec::Builder::BuildResults.parse(<<~YAML, file: File.join(@dir, "build-results.yml"), release: "child", target: target)
      relspec_build_results: 1
      release: child
      target: bookworm/amd64
      backend: host
      packages:
        rock-types: { package: base/types, version: 2.0-1, status: failed, duration: 3.5, log: logs/rock-types.log, reason: "rock-types: dpkg-buildpackage failed" }
        rock-io: { package: drivers/io, version: 1.0-1, status: skipped, reason: build-dependency rock-types failed }
        rock-ui: { package: tools/ui, version: 0.1-1, status: skipped, reason: build-dependency rock-types failed }
    YAML
  end

  around do |example|
    Dir.mktmpdir do |dir|
      @dir = dir
      FileUtils.mkdir_p(File.join(dir, "logs"))
      File.write(File.join(dir, "logs", "rock-types.log"), "$ dpkg-buildpackage\nCMake Error: <types>\n")
      example.run
    end
  end

  def read(ancestor_lock: nil)
    input = Relspec::TargetBuild.new(target: target, dir: @dir, plan: plan, results: results)
    # the diff counts commits with git, which a unit test does not run: nothing to count here
    counter = Struct.new(:none) { def count(*) = nil }.new
    described_class.new(lock: child_lock, inputs: [input], ancestor: "base", ancestor_lock: ancestor_lock,
                        counter: counter).page
  end

  it "gives every package its decision, version and build, the failure's first error and its log" do
    page, logs = read
    view = page.targets.first
    cells = view.cells.to_h { |cell| [cell.package, cell] }
    expect(cells["base/cmake"].to_h).to eq("package" => "base/cmake", "decision" => "inherit", "from" => "base",
                                           "version" => "1.0-1")
    expect(cells["base/types"].to_h).to include("status" => "failed", "first_error" => "CMake Error: <types>",
                                                "log" => "logs/bookworm-amd64/rock-types.log", "duration" => 3.5)
    expect(logs).to eq("logs/bookworm-amd64/rock-types.log" => File.join(@dir, "logs", "rock-types.log"))
    expect(cells["tools/ui"].blocked_by).to eq(["rock-types"]) # through drivers/io
    expect(cells["tools/new"].status).to eq("not built yet")
    expect(cells["tools/ui"].causes).to eq(["depends on drivers/io", "depends on base/types", blacklisted])
    expect(view.totals).to include("inherit" => 1, "build" => 4, "failed" => 1, "skipped" => 2, "not built yet" => 1,
                                   "built" => 0)
    expect(view.blockers.map(&:to_h)).to eq([{ "source" => "rock-types", "package" => "base/types",
                                               "blocked" => ["drivers/io", "tools/ui"] }])
    expect(view.critical_path.map(&:source)).to eq(["rock-types"])
    expect(view.changes).to be_nil
    expect(page.ancestor).to be_nil
  end

  it "lists what changed against the ancestor's lock, with the diff's wording" do
    page, = read(ancestor_lock: lock("base", "base/cmake" => entry("build", "1.0-1"),
                                             "base/types" => entry("build", "1.9-1", causes: ["missing in all ancestors"])))
    changes = page.targets.first.changes.to_h { |change| [change.package, change.to_h] }
    expect(page.ancestor).to eq("base")
    expect(changes["base/cmake"]).to eq("package" => "base/cmake", "change" => "build → inherit", "old" => "build 1.0-1",
                                        "new" => "inherit 1.0-1 from base")
    expect(changes["tools/new"]).to include("change" => "added", "new" => "build 0.2-1")
  end

  # docs/abi.md: a candidate the build kept, and one the lock records kept
  # once published, are shown kept with why.
  it "shows a kept candidate with why, from its record or from the lock" do
    kept_results = Relspec::Builder::BuildResults.parse(<<~YAML, file: File.join(@dir, "build-results.yml"), release: "child", target: target)
      relspec_build_results: 1
      release: child
      target: bookworm/amd64
      backend: host
      packages:
        rock-io: { package: drivers/io, version: 1.0-1, status: kept, cutoff: { keeps: 1.0-0, verdict: keep, reason: the interface of rock-types did not change, evidence: ["rock-types: 3 files compared with 1.9-1, unchanged"] } }
    YAML
    published = lock("child", "tools/ui" => Relspec::Plan::Lock::Entry.new(decision: "published", deb: "rock-ui", version: "0.1-1",
                                                                           kept: "the interface of rock-io did not change"),
                              "drivers/io" => entry("build", "1.0-1"))
    input = Relspec::TargetBuild.new(target: target, dir: @dir, plan: plan, results: kept_results)
    page, = described_class.new(lock: published, inputs: [input], counter: Struct.new(:none) { def count(*) = nil }.new).page
    cells = page.targets.first.cells.to_h { |cell| [cell.package, cell] }
    expect([cells["drivers/io"].status, cells["drivers/io"].reason])
      .to eq(["kept", "kept at 1.0-0: the interface of rock-types did not change (rock-types: 3 files compared with 1.9-1, unchanged)"])
    expect([cells["tools/ui"].status, cells["tools/ui"].reason]).to eq(["kept", "kept at 0.1-1: the interface of rock-io did not change"])
    expect(page.targets.first.totals).to include("kept" => 2, "published" => 1)
  end

  it "refuses a log that is a symbolic link, or one below a linked folder, naming the link (it could publish any file)" do
    FileUtils.rm(File.join(@dir, "logs", "rock-types.log"))
    File.symlink("/etc/hostname", File.join(@dir, "logs", "rock-types.log"))
    expect { read }.to raise_error(Relspec::Error, "#{@dir}/logs/rock-types.log is a symbolic link (to /etc/hostname): " \
                                                   "the report reads a build's logs only inside #{@dir}, never through " \
                                                   "a link; remove the link and build again")
    FileUtils.mv(File.join(@dir, "logs"), File.join(@dir, "elsewhere"))
    File.symlink("elsewhere", File.join(@dir, "logs"))
    expect { read }.to raise_error(Relspec::Error, %r{\A#{@dir}/logs is a symbolic link \(to elsewhere\)})
  end
end
