# frozen_string_literal: true

require "spec_helper"
require "json"
require "digest"
require_relative "../../support/real_rock_workspace"

# ABI verdicts on real code: base/logging (the real repository in
# ../shared) built with the host backend into a parent release (pinned at
# b2b4a49, June 2016) and two children. "same" blacklists base/logging and
# so rebuilds it from the parent's source: unchanged. "changed" pins the
# later revision c7bc000 and carries an overlay patch that adds a data
# member to base::logging::Logger: abidiff sees the class grow and its
# members move. (base/logging's own history has no ABI change among the
# revisions that build on their own: abidiff of b2b4a49, 861be5f and
# c7bc000 reports nothing, so the layout change is the patch's.)
RSpec.describe "relspec abi on a real library", :tmpdir do
  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @root = Dir.mktmpdir("relspec-abi")
    workspace = RealRockWorkspace.shared.root
    write_spec("parent", <<~YAML, workspace)
      select: [base/logging]
      targets: { bookworm: [amd64] }
      maintainer: Demo <demo@example.org>
      pins:
        base/logging: { commit: b2b4a49 }
      repository: { path: ../repos/parent, trusted: true }
    YAML
    write_spec("same", <<~YAML, workspace)
      parent: parent
      select: [base/logging]
      blacklist:
        - { match: base/logging, reason: rebuilt from the parent's source }
      repository: { path: ../repos/same, trusted: true, debug_symbols: true }
    YAML
    write_spec("changed", <<~YAML, workspace)
      parent: parent
      select: [base/logging]
      pins:
        base/logging: { commit: c7bc000 }
      repository: { path: ../repos/changed, trusted: true }
    YAML
    build("parent")
    run!("publish", "specs/parent.yml", "--out", "out")
    build("same")
    # the overlay exists only once parent and same are built from the plain source
    patch = File.join(@root, "overlays", "base", "logging", "patches", "logger-line-length.patch")
    FileUtils.mkdir_p(File.dirname(patch))
    # adds a data member before the others (git diff against c7bc000)
    FileUtils.cp(File.expand_path("../../fixtures/abi/logger-line-length.patch", __dir__), patch)
    build("changed")
  end

  after(:all) { FileUtils.rm_rf(@root) if @root }

  def write_spec(name, yaml, workspace)
    FileUtils.mkdir_p(File.join(@root, "specs"))
    File.write(File.join(@root, "specs", "#{name}.yml"), "release: #{name}\nworkspace: #{workspace}\n#{yaml}")
  end

  def build(name)
    run!("compile", "specs/#{name}.yml", "--out", "out")
    run!("build", "specs/#{name}.yml", "--out", "out", "--backend", "host")
  end

  def run!(*args)
    run = relspec(*args, chdir: @root)
    raise "relspec #{args.join(' ')}: #{run.stdout}#{run.stderr}" unless run.status.success?

    run
  end

  def dump(release)
    File.join(@root, "out", release, "bookworm-amd64", "results", "rock-#{release}-base-logging",
              "libbase-logging.so.abi.xml.gz")
  end

  it "dumps each shipped library with every build, records it and publishes it beside the repository" do
    results = YAML.safe_load_file(File.join(@root, "out", "parent", "bookworm-amd64", "build-results.yml"))
    names = results["packages"].transform_values { |record| record["files"].map { |file| file["name"] } }
    expect(names["rock-parent-base-logging"]).to include("results/rock-parent-base-logging/libbase-logging.so.abi.xml.gz")
    expect(names["rock-parent-base-cmake"].grep(/abi/)).to be_empty # no shared library there
    # rebuilt from the same source in another release: the same bytes
    expect(Digest::SHA256.file(dump("same")).hexdigest).to eq(Digest::SHA256.file(dump("parent")).hexdigest)
    index = YAML.safe_load_file(File.join(@root, "repos", "parent", "abi", "bookworm-amd64", "index.yml"))
    expect(index["dumps"]).to eq([{ "package" => "base/logging", "source" => "rock-parent-base-logging",
                                    "version" => index["dumps"].first["version"], "library" => "libbase-logging.so",
                                    "file" => "rock-parent-base-logging/libbase-logging.so.abi.xml.gz",
                                    "sha256" => Digest::SHA256.file(dump("parent")).hexdigest }])
  end

  it "publishes the -dbgsym .deb the dumps were made from only when the spec asks for it" do
    results = YAML.safe_load_file(File.join(@root, "out", "parent", "bookworm-amd64", "build-results.yml"))
    recorded = results["packages"]["rock-parent-base-logging"]["files"].map { |file| File.basename(file["name"]) }
    expect(recorded.grep(/\Arock-parent-base-logging-dbgsym_.*_amd64\.deb\z/).size).to eq(1) # kept by the build
    # parent, published in before(:all), does not ask
    parent = File.join(@root, "repos", "parent")
    expect(Dir.glob("pool/**/*.deb", base: parent).grep(/dbgsym/)).to eq([])
    expect(File.read(File.join(parent, "dists", "bookworm", "main", "binary-amd64", "Packages"))).not_to include("dbgsym")
    # same says debug_symbols: true
    run!("publish", "specs/same.yml", "--out", "out")
    same = File.join(@root, "repos", "same")
    expect(Dir.glob("pool/**/*.deb", base: same).grep(/dbgsym/))
      .to match([a_string_matching(%r{\Apool/main/r/rock-same-base-logging/rock-same-base-logging-dbgsym_.*_amd64\.deb\z})])
    expect(File.read(File.join(same, "dists", "bookworm", "main", "binary-amd64", "Packages")))
      .to include("Package: rock-same-base-logging-dbgsym\n")
    osdeps = File.read(File.join(same, "osdeps", "same-amd64.yml"))
    expect(osdeps).to include("rock-same-base-logging")
    expect(osdeps).not_to include("dbgsym")
  end

  it "names a library rebuilt from the same source unchanged" do
    run = relspec("abi", "specs/same.yml", "--out", "out", "--fail-on", "changed", chdir: @root)
    expect(run.status.exitstatus).to eq(0), run.stderr
    expect(run.stdout).to eq("same bookworm/amd64: 1 library: 1 unchanged\n  " \
                             "libbase-logging.so (base/logging): unchanged against parent\n")
  end

  it "names the grown class changed, with what moved, and fails a review that asks for it" do
    run = relspec("abi", "specs/changed.yml", "--out", "out", "--fail-on", "changed", chdir: @root)
    expect(run.status.exitstatus).to eq(1), run.stderr
    expect(run.stdout).to include("libbase-logging.so (base/logging): changed against parent")
    expect(run.stdout).to include("'unsigned int mMaxLineLength', at offset 64 (in bits)")
    expect(run.stdout).to include("'FILE* mStream' offset changed from 64 to 128 (in bits)")
    expect(relspec("abi", "specs/changed.yml", "--out", "out", "--fail-on", "incompatible", chdir: @root).status.exitstatus).to eq(0)

    json = JSON.parse(run!("abi", "specs/changed.yml", "--out", "out", "--format", "json").stdout)
    entry = json.fetch("targets").fetch("bookworm/amd64").first
    expect(entry.slice("package", "library", "verdict", "against"))
      .to eq("package" => "base/logging", "library" => "libbase-logging.so", "verdict" => "changed", "against" => "parent")
    expect(entry["summary"].first).to start_with("Functions changes summary: 0 Removed, 1 Changed")
  end

  it "shows the verdicts of the libraries a change builds in relspec diff's markdown and json, with --abi-out" do
    locks = ["releases/same/lock.yml", "releases/changed/lock.yml"]
    json = JSON.parse(run!("diff", *locks, "--format", "json", "--abi-out", "out").stdout)
    expect(json.fetch("abi").fetch("changed").fetch("bookworm/amd64").map { |entry| entry.values_at("package", "verdict", "against") })
      .to eq([["base/logging", "changed", "parent"]])
    markdown = run!("diff", *locks, "--format", "markdown", "--abi-out", "out").stdout
    expect(markdown).to include("### ABI of changed on bookworm/amd64\n\n1 library: 1 changed\n")
    expect(markdown).to include("'unsigned int mMaxLineLength', at offset 64 (in bits)")
    expect(run!("diff", *locks, "--format", "json").stdout).not_to include('"abi"') # only when asked
  end

  # Temporarily replaces +path+ with +content+ while the block runs.
  def replaced(path, content)
    saved = File.binread(path)
    File.binwrite(path, content)
    yield
  ensure
    File.binwrite(path, saved)
  end

  it "refuses a damaged published index with its file and line, and a dump changed since it was recorded" do
    index = File.join(@root, "repos", "parent", "abi", "bookworm-amd64", "index.yml")
    replaced(index, File.read(index).sub(/file: .*/, "file: ../../../etc/libx.so.abi.xml.gz")) do
      run = relspec("abi", "specs/same.yml", "--out", "out", chdir: @root)
      expect(run.status.exitstatus).to eq(1)
      expect(run.stderr).to match(%r{index\.yml:\d+:\d+: error\[abi-index\]: cannot read the ABI index: dumps\.0\.file "\.\./\.\./\.\./etc/libx\.so\.abi\.xml\.gz" is not a plain path})
      expect(run.stderr).not_to include("from /")
    end
    replaced(dump("same"), "not a dump") do
      run = relspec("abi", "specs/same.yml", "--out", "out", chdir: @root)
      expect(run.status.exitstatus).to eq(1)
      expect(run.stderr).to include("libbase-logging.so.abi.xml.gz has changed since it was recorded")
    end
  end

  it "refuses an --against that is neither the release nor an ancestor, naming those" do
    run = relspec("abi", "specs/changed.yml", "--out", "out", "--against", "nightly", chdir: @root)
    expect(run.status.exitstatus).to eq(1)
    expect(run.stderr).to include("--against nightly: not changed or one of its ancestors with a repository (changed, parent)")
  end
end
