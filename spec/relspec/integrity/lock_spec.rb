# frozen_string_literal: true

require "spec_helper"
require "relspec/plan"

# The lock is read as strictly as it is written: a lock relspec cannot read
# stops plan, why and compile with file:line, and is never overwritten
# unless the user says --discard-lock.
RSpec.describe "the lock file" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-lock")
    @fixture = ReleaseFixture.new(@dir)
    @fixture.standalone("rel", select: ["base/cmake"], targets: "bionic: [amd64]")
    @compiled = relspec("compile", "specs/rel.yml", "--out", "out", chdir: @dir)
    @lock_path = File.join(@dir, "releases", "rel", "lock.yml")
    @good = File.binread(@lock_path)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after { File.binwrite(@lock_path, @good) }

  it "is read back into the same lock it was written from" do
    expect(@compiled.exit_code).to eq(0), @compiled.stderr
    lock = Relspec::Plan::LockParser.read(@lock_path, release: "rel")
    expect(Relspec::Plan::LockGenerator.dump(lock)).to eq(@good)
    expect(lock.history.build("bionic/amd64", "base/cmake", "1.0.20200504.080000").revision).to eq(1)
    # a build records what its debian/ names, here nothing
    expect(lock.targets.dig("bionic/amd64", "base/cmake").depends).to eq([])
  end

  it "reads a lock written before builds recorded their dependencies" do
    File.binwrite(@lock_path, @good.sub(/^ +depends: \[\]\n/, ""))
    lock = Relspec::Plan::LockParser.read(@lock_path, release: "rel")
    expect(lock.targets.dig("bionic/amd64", "base/cmake").depends).to be_nil
    run = relspec("plan", "specs/rel.yml", "--check", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to include("releases/rel/lock.yml: out of date\n  the builds' recorded dependencies (depends:) differ")
  end

  damaged = {
    "invalid YAML" => ["relspec_lock: 2\nrelease: [rel\n", /lock.yml:\d+:\d+: error\[lock\]: invalid YAML/],
    "a list" => ["- relspec_lock\n- 2\n", /lock.yml:1:1: error\[lock\]: cannot read the lock: the lock is empty or not a mapping/],
    "an unknown format" => ["relspec_lock: 3\nrelease: rel\n", /lock.yml:1:15: error\[lock\]: .*unknown lock format 3/],
    "empty" => ["", /lock.yml:1:1: error\[lock\]: cannot read the lock: the lock is empty/],
    "binary" => ["\x00\x01\xFF\xFEgarbage".b, /lock.yml(:\d+:\d+)?: error\[lock\]/],
    "a revision of the wrong type" => [:revision, /lock.yml:\d+:\d+: error\[lock\]: .*revision must be a positive whole number/],
    "a list where targets belong" => [:targets, /lock.yml:\d+:\d+: error\[lock\]: .*targets must be a mapping/],
    "an invalid version" => [:version, /lock.yml:\d+:\d+: error\[lock\]: .*invalid Debian version "not a version"/],
    "depends that is not a list of names" => [:depends, /lock.yml:\d+:\d+: error\[lock\]: .*depends must be a list of text/],
    "another release's lock" => [:release, /lock.yml:3:\d+: error\[lock\]: .*the lock is of release other, not rel/]
  }

  def damage(kind)
    case kind
    when :revision then @good.sub("revision: 1", "revision: one")
    when :targets then @good.sub(/^targets:\n(  .*\n)+/, "targets: [a, b]\n")
    when :version then @good.sub('version: "1.0.20200504.080000-1~bionic"', 'version: "not a version"')
    when :release then @good.sub("release: rel", "release: other")
    when :depends then @good.sub("depends: []", "depends: 5")
    else kind
    end
  end

  damaged.each do |what, (content, message)|
    it "refuses #{what}: one message with file:line, exit 1, the lock untouched" do
      bytes = damage(content)
      expect(bytes).not_to eq(@good)
      File.binwrite(@lock_path, bytes)
      %w[plan compile].each do |command|
        args = command == "compile" ? ["--out", "out"] : ["--write"]
        run = relspec(command, "specs/rel.yml", *args, chdir: @dir)
        expect(run.exit_code).to eq(1), "#{command}: #{run.stderr}"
        expect(run.stderr).to match(message)
        expect(run.stderr).to include("--discard-lock")
        expect(run.stderr).not_to match(/\.rb:\d+:in /)
        expect(File.binread(@lock_path)).to eq(bytes)
      end
    end
  end

  it "starts over with --discard-lock, saying what is lost, and never gives a published revision again" do
    builder = AptRepositoryBuilder.new(File.join(@dir, "repos", "rel"), codenames: ["bionic"], architectures: ["amd64"])
    builder.add("rock-rel-base-cmake", "1.0.20200504.080000-1~bionic", codename: "bionic", arch: "amd64")
    @fixture.spec("rel", "select: [base/cmake]\ntargets: { bionic: [amd64] }\nmaintainer: Demo <demo@example.org>\n" \
                         "repository: { path: ../repos/rel, trusted: true }\n", workspace: :checkouts)
    File.binwrite(@lock_path, "relspec_lock: [broken\n")
    run = relspec("plan", "specs/rel.yml", "--write", "--discard-lock", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stderr).to include("discarding releases/rel/lock.yml", "revisions and debian/ digests of earlier builds are forgotten")
    lock = YAML.safe_load(File.read(@lock_path))
    # the repository holds -1, which nothing vouches for now: the next build is -2
    expect(lock.dig("targets", "bionic/amd64", "base/cmake", "version")).to eq("1.0.20200504.080000-2~bionic")
  ensure
    FileUtils.rm_rf(File.join(@dir, "repos"))
    @fixture.standalone("rel", select: ["base/cmake"], targets: "bionic: [amd64]")
  end

  it "compiles with --discard-lock, saying so, and writes a lock that reads again" do
    File.binwrite(@lock_path, "\x00\xff binary")
    run = relspec("compile", "specs/rel.yml", "--out", "out", "--discard-lock", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stderr).to include("discarding releases/rel/lock.yml")
    expect(Relspec::Plan::LockParser.read(@lock_path, release: "rel").packages.keys).to include("base/cmake")
    again = relspec("compile", "specs/rel.yml", "--out", "out", chdir: @dir)
    expect(again.exit_code).to eq(0), again.stderr
    expect(again.stderr).not_to include("discarding")
  ensure
    FileUtils.rm_rf(File.join(@dir, "out"))
  end

  it "reads a format 1 lock, whose recorded builds become the history" do
    data = YAML.safe_load(@good)
    digest = data.dig("targets", "bionic/amd64", "base/cmake", "debian_digest")
    version1 = data.merge("relspec_lock" => 1).except("history")
    version1["targets"]["bionic/amd64"]["base/cmake"]["version"] = "1.0.20200504.080000-3~bionic"
    File.write(@lock_path, Relspec::Yaml::Writer.dump(version1))
    lock = Relspec::Plan::LockParser.read(@lock_path, release: "rel")
    expect(lock.history.build("bionic/amd64", "base/cmake", "1.0.20200504.080000").to_h)
      .to eq(revision: 3, debian_digest: digest, kept: nil)
    expect(JSON.parse(relspec("plan", "specs/rel.yml", "--format", "json", chdir: @dir).stdout)
             .dig("targets", "bionic/amd64", "base/cmake", "version")).to eq("1.0.20200504.080000-3~bionic")
  end
end
