# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "relspec/plan"

# Gem osdeps packaged without `gems:` (issue 15, item 3): a real autoproj
# workspace whose packages name the gem foo in their osdeps, real .gem files
# (GemBuilder) served by a WEBrick server with the compact index rubygems.org
# serves (/info/<name>), and a reprepro archive standing for bookworm that
# has ruby-baz, an old ruby-bar and no ruby-foo.
#
#   foo 1.0.0, 1.5.0 need bar >= 1.0 and baz >= 1.0; foo 2.0.0 needs bar >= 1.1
#   bar 1.0.0, 1.1.0 (the archive's ruby-bar 0.5 is too old)
#   baz: no .gem at all (the archive's ruby-baz 1.2.0 is what is used)
RSpec.describe "gem osdeps resolved against the distribution and gem_source" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-gem-resolution")
    builder = WorkspaceBuilder.new(File.join(@dir, "ws"))
    builder.package("tools/app", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: ["foo"])
    builder.package("tools/old_app", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: ["foo_v1"])
    builder.package("tools/ancient_app", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: ["foo_ancient"])
    builder.package("tools/loop_app", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: ["loopa"])
    builder.osdeps("foo:\n  gem: foo\nfoo_v1:\n  gem: foo<2.0\nfoo_ancient:\n  gem: foo<0.5\nloopa:\n  gem: loopa\n")
    builder.create
    gems = File.join(@dir, "server", "gems")
    @foo_dependencies = { "bar" => ">= 1.0", "baz" => ">= 1.0" }
    %w[1.0.0 1.5.0].each { |version| GemBuilder.build(gems, "foo", version, dependencies: @foo_dependencies) }
    GemBuilder.build(gems, "foo", "2.0.0", dependencies: { "bar" => ">= 1.1", "baz" => ">= 1.0" })
    %w[1.0.0 1.1.0].each { |version| GemBuilder.build(gems, "bar", version) }
    GemBuilder.build(gems, "loopa", "1.0.0", dependencies: { "loopb" => ">= 1.0" })
    GemBuilder.build(gems, "loopb", "1.0.0", dependencies: { "loopa" => ">= 1.0" })
    GemBuilder.compact_index(File.join(@dir, "server"))
    @server = HttpServer.new(File.join(@dir, "server"))
    archive = AptRepositoryBuilder.new(File.join(@dir, "repos", "debian"), codenames: ["bookworm"], architectures: ["amd64"])
    archive.add("ruby-baz", "1.2.0-1", codename: "bookworm", arch: "amd64")
    archive.add("ruby-bar", "0.5.0-2", codename: "bookworm", arch: "amd64")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  ARCHIVE = "distributions:\n  bookworm: { archive: { path: ../repos/debian, trusted: true } }\n"

  def spec(name, body, source: @server.url, archive: ARCHIVE)
    File.write(File.join(@dir, "specs", "#{name}.yml"),
               "release: #{name}\nworkspace: ../ws/workspace\ntargets: { bookworm: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\ngem_source: #{source}\n#{archive}#{body}")
    File.join(@dir, "specs", "#{name}.yml")
  end

  def decisions(path)
    result = Relspec::Plan.run(path, cache_dir: nil)
    [result.plan.targets.fetch(Relspec::Plan::Target.parse("bookworm/amd64")).transform_values(&:to_h), result]
  end

  it "packages foo at the highest version and bar, takes ruby-baz, and never asks the source for baz" do
    before = @server.requests.size
    plan, result = decisions(spec("auto", "select: [tools/app]\n"))
    expect(plan["foo"]).to include("decision" => "build", "deb" => "rock-auto-ruby-foo", "version" => "2.0.0-1~bookworm")
    expect(plan["bar"]).to include("decision" => "build", "version" => "1.1.0-1~bookworm")
    expect(plan.keys).not_to include("baz")
    catalog = result.catalog
    expect(catalog.package("foo").dependencies).to eq(["bar"])
    # foo's requirement on baz reaches its debian/control as a relation on ruby-baz
    baz = catalog.package("foo").os_dependencies_for("bookworm")
    expect(baz.gems).to eq(["baz>= 1.0"])
    expect(Relspec::Debian::ControlRelations.distribution_gems(baz, %w[foo bar])).to eq(["ruby-baz (>= 1.0)"])
    expect(catalog.package("tools/app").dependencies).to include("foo")
    asked = @server.requests.drop(before)
    # (the .gem files themselves may come from the download cache of an earlier example)
    expect(asked).to include("/info/foo", "/info/bar")
    expect(asked.grep(/baz/)).to eq([])
    expect(result.plan.notes).to include("the bookworm archive has no ruby-foo: gem foo is packaged here")
  end

  it "keeps to an osdeps constraint: foo<2.0 takes foo 1.5.0" do
    plan, = decisions(spec("old", "select: [tools/old_app]\n"))
    expect(plan["foo"]).to include("decision" => "build", "version" => "1.5.0-1~bookworm")
    expect(plan["bar"]).to include("decision" => "build", "version" => "1.1.0-1~bookworm")
  end

  # A release +name+ of tools/app whose gem_source is a folder holding the
  # server's gems matching +pattern+, planned with its lock written.
  # Returns [folder, spec path].
  def planned_from_folder(name, pattern)
    folder = File.join(@dir, "#{name}-gems")
    FileUtils.mkdir_p(folder)
    FileUtils.cp(Dir.glob(File.join(@dir, "server", "gems", pattern)), folder)
    path = spec(name, "select: [tools/app]\n", source: "../#{name}-gems")
    run = relspec("plan", path, "--write", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    [folder, path]
  end

  it "records the versions in the lock and keeps them while they fit, though gem_source has a newer one" do
    folder, path = planned_from_folder("stable", "*.gem")
    lock = YAML.safe_load(File.read(File.join(@dir, "releases", "stable", "lock.yml")))
    expect(lock.dig("packages", "foo")).to include("url" => "../stable-gems/foo-2.0.0.gem", "version" => "2.0.0")
    expect(lock.dig("packages", "bar")).to include("url" => "../stable-gems/bar-1.1.0.gem", "version" => "1.1.0")

    GemBuilder.build(folder, "foo", "2.1.0", dependencies: @foo_dependencies)
    plan, = decisions(path)
    expect(plan["foo"]).to include("version" => "2.0.0-1~bookworm")
    # without the lock, the newer one is taken
    fresh, = decisions(spec("fresh", "select: [tools/app]\n", source: "../stable-gems"))
    expect(fresh["foo"]).to include("version" => "2.1.0-1~bookworm")
  end

  it "refuses a packaged gem whose .gem changed under the version the lock recorded, on gem_source" do
    folder, = planned_from_folder("changing", "{foo,bar}-*.gem")
    GemBuilder.build(folder, "foo", "2.0.0", dependencies: { "bar" => ">= 1.1", "baz" => ">= 1.0" }, date: "2021-03-03")
    run = relspec("plan", "specs/changing.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("specs/changing.yml:5:1: error[gem-changed]: gem foo 2.0.0 from " \
                                  "../changing-gems/foo-2.0.0.gem is not the .gem the lock recorded")
  end

  it "takes the version of gems: over the highest one" do
    plan, = decisions(spec("pinned", "select: [tools/app]\ngems: { foo: \"1.0.0\" }\n"))
    expect(plan["foo"]).to include("decision" => "build", "version" => "1.0.0-1~bookworm")
    expect(plan["bar"]).to include("version" => "1.1.0-1~bookworm")
  end

  it "takes a gems: entry the distribution has from it without its .gem" do
    before = @server.requests.size
    path = spec("provided", "select: [tools/app]\ngems: { baz: \"1.2.0\" }\n")
    plan, = decisions(path)
    expect(plan["baz"]).to eq("decision" => "system", "deb" => "ruby-baz", "version" => "1.2.0-1")
    # its lock entry (no .gem URL, no SHA256) reads back
    2.times { expect(relspec("plan", path, "--write", chdir: @dir).exit_code).to eq(0) }
    expect(@server.requests.drop(before).grep(/baz/)).to eq([])
  end

  it "stops with one error naming the package, its osdep and the constraint when no version fits" do
    spec("none", "select: [tools/ancient_app]\n")
    run = relspec("plan", "specs/none.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[gem-unresolvable]: no version of gem foo in #{@server.url}/info/<name> fits what " \
                                  "is asked: tools/ancient_app's osdep foo<0.5 (< 0.5); it has 2.0.0, 1.5.0, 1.0.0")
    expect(run.stderr.scan("error[").size).to eq(1)
    expect(run.stderr).not_to include("Traceback", ".rb:")
  end

  it "ends on a dependency cycle, with one error: packages that build-depend on each other cannot be built" do
    spec("loop", "select: [tools/loop_app]\n")
    run = relspec("plan", "specs/loop.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[gem-cycle]: gems loopa → loopb → loopa need each other")
    expect(run.stderr).not_to include("Traceback", ".rb:")
  end

  it "says once that a target without an archive is not checked, and packages nothing there" do
    path = spec("unchecked", "select: [tools/app]\n", archive: "")
    plan, result = decisions(path)
    expect(plan.keys).not_to include("foo", "bar")
    expect(result.plan.notes.grep(/gem osdeps/))
      .to eq(["gem osdeps are not checked on bookworm/amd64 (no distribution archive: distributions.<codename>.archive): " \
              "foo taken as ruby-<gem> there"])
  end
end
