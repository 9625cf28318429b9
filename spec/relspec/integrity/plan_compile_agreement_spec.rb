# frozen_string_literal: true

require "spec_helper"
require "digest"
require "yaml"

# DESIGN §12: the version `plan` and `why` print is the version `compile`
# writes, and a name in the build tree never stands for two different files.
#
# The release's own repository is a real reprepro repository; the packages
# "published" into it are stand-in .debs named and versioned from the lock
# (building them for real is the builder's job and its tests').
RSpec.describe "plan, why and compile agree" do
  around do |example|
    Dir.mktmpdir("relspec-agree") do |dir|
      @dir = dir
      @fixture = ReleaseFixture.new(dir)
      @fixture.repository("parent", [%w[bionic amd64]], ReleaseFixture::LAYOUT.to_h { |name| [name, {}] })
      @fixture.spec("parent", "targets: { bionic: [amd64] }\nrepository: { path: ../repos/parent, trusted: true }\n" \
                              "maintainer: Demo Packaging <demo@example.org>\n")
      example.run
    end
  end

  def child(pin: "{ tag: v2.0.0 }", blacklist: %w[base/types], select: nil)
    entries = blacklist.map { |name| "  - { match: #{name}, reason: test }\n" }.join
    yaml = +"parent: parent\nrepository: { path: ../repos/child, trusted: true }\n"
    yaml << "blacklist:\n#{entries}" unless blacklist.empty?
    yaml << "pins: { base/types: #{pin} }\n" if pin
    yaml << "select: [#{select.join(', ')}]\n" if select
    @fixture.spec("child", yaml, workspace: :checkouts)
  end

  def compile
    run = relspec("compile", "specs/child.yml", "--out", "out", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    run
  end

  def lock
    YAML.safe_load(File.read(File.join(@dir, "releases", "child", "lock.yml")))
  end

  def why_version(package)
    run = relspec("why", "specs/child.yml", package, "--target", "bionic/amd64", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    run.stdout[/ as \S+ (\S+)/, 1].delete_suffix(",")
  end

  def written_version(package)
    plan = YAML.safe_load(File.read(File.join(@dir, "out", "child", "bionic-amd64", "plan.yml")))
    plan["builds"].find { |build| build["package"] == package }&.fetch("version")
  end

  def publish_from_lock
    builder = AptRepositoryBuilder.new(File.join(@dir, "repos", "child"), codenames: ["bionic"], architectures: ["amd64"])
    builds = lock.dig("targets", "bionic/amd64").select { |_, entry| entry["decision"] == "build" }
    builder.add_many(builds.map { |_, entry| { name: entry["deb"], version: entry["version"], arch: "amd64" } },
                     codename: "bionic")
  end

  it "gives a dependent of a re-pinned package its next revision in plan, why and compile alike" do
    child
    compile
    publish_from_lock
    expect(relspec("plan", "specs/child.yml", chdir: @dir).stdout).to match(%r{bionic/amd64\s+4\s+0\s+3$})

    head = @fixture.builder.commit_of("base/types")
    child(pin: "{ commit: #{head} }")
    planned = JSON.parse(relspec("plan", "specs/child.yml", "--format", "json", chdir: @dir).stdout)
    dependent = planned.dig("targets", "bionic/amd64", "drivers/iodrivers_base")
    expect(dependent).to include("decision" => "build")
    expect(dependent["version"]).to end_with("-2~bionic")
    said = why_version("drivers/iodrivers_base")
    expect(said).to eq(dependent["version"])
    compile
    expect(written_version("drivers/iodrivers_base")).to eq(said)
    expect(Dir.glob(File.join(@dir, "out", "child", "bionic-amd64", "*", "*.dsc")).map { |path| File.basename(path) })
      .to include("rock-child-drivers-iodrivers-base_#{said}.dsc")
  end

  it "never takes back a revision when a package leaves the selection and comes back" do
    selected = %w[base/types drivers/iodrivers_base]
    child(select: selected)
    compile
    FileUtils.mkdir_p(File.join(@dir, "overlays", "drivers", "iodrivers_base", "debian"))
    File.write(File.join(@dir, "overlays", "drivers", "iodrivers_base", "debian", "NOTE"), "two\n")
    compile
    second = written_version("drivers/iodrivers_base")
    expect(second).to end_with("-2~bionic")

    child(select: ["base/types"])
    compile
    expect(written_version("drivers/iodrivers_base")).to be_nil
    child(select: selected)
    compile
    expect(written_version("drivers/iodrivers_base")).to eq(second)
  end

  # Random sequences of spec edits, compile after each. Across the whole
  # sequence: no file name with two contents, revisions never go down for
  # an upstream version, and `why` prints what compile writes.
  [11, 23].each do |seed|
    it "keeps names unique, revisions rising and why truthful over random edits (seed #{seed})" do
      random = Random.new(seed)
      head = @fixture.builder.commit_of("base/types")
      seen = {}
      revisions = {}
      state = { pin: "{ tag: v2.0.0 }", blacklist: %w[base/types], select: nil, note: nil }
      edits = [
        -> { state[:pin] = ["{ tag: v2.0.0 }", "{ commit: #{head} }", nil].sample(random: random) },
        -> { state[:blacklist] = [%w[base/types], %w[base/types data/models], %w[base/logging]].sample(random: random) },
        -> { state[:select] = [nil, %w[base/types drivers/iodrivers_base], %w[base/types]].sample(random: random) },
        -> { state[:note] = [nil, "one\n", "two\n"].sample(random: random) }
      ]
      8.times do
        edits.sample(random: random).call
        note = File.join(@dir, "overlays", "base", "types", "debian", "NOTE")
        FileUtils.rm_f(note)
        if state[:note]
          FileUtils.mkdir_p(File.dirname(note))
          File.write(note, state[:note])
        end
        child(pin: state[:pin], blacklist: state[:blacklist], select: state[:select])
        compile

        Dir.glob(File.join(@dir, "out", "child", "bionic-amd64", "*", "*")).each do |path|
          name = File.basename(path)
          next unless name.match?(/\.(orig\.tar\.gz|debian\.tar\.xz|dsc)\z/)

          digest = Digest::SHA256.file(path).hexdigest
          expect(seen.fetch(name, digest)).to eq(digest), "#{name} was written with two different contents"
          seen[name] = digest
        end
        lock.fetch("history").fetch("bionic/amd64").each do |package, upstreams|
          upstreams.each do |upstream, build|
            key = [package, upstream]
            expect(build["revision"]).to be >= revisions.fetch(key, 0), "#{key} went back to #{build['revision']}"
            revisions[key] = build["revision"]
          end
        end
        built = YAML.safe_load(File.read(File.join(@dir, "out", "child", "bionic-amd64", "plan.yml")))["builds"]
        sample = built.sample(random: random)
        expect(why_version(sample["package"])).to eq(sample["version"]) if sample
      end
      expect(seen.size).to be > 6
    end
  end
end
