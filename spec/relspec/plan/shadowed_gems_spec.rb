# frozen_string_literal: true

require "spec_helper"
require "relspec/plan"

# A distribution gem that depends on a gem the release packages itself is
# packaged too (issue 44: on trixie, Debian's ruby-dry-types 1.2.2, made for
# dry-core 0.7, ran beside the release's dry-core 1.2.0). The trixie core
# release's gems in small, with their parts real: a real autoproj
# workspace, real .gem files served with rubygems.org's compact index by a
# WEBrick server on 127.0.0.1, and reprepro archives for bookworm and
# trixie whose ruby-* packages carry Debian's Depends.
#
#   web 4.1.0 (grape)         needs conf >= 1.0, types >= 1.1, extra, plain;
#                             bookworm has ruby-web 1.6.2-3, trixie none
#   web_logging 3.0.1         needs web >= 2.0; bookworm has
#     (grape_logging)         ruby-web-logging 1.8.4-1 (Depends: ruby-web), trixie none
#   conf 1.4.0 (dry-configurable)  needs core ~> 1.0; both have ruby-conf 0.9.0-2
#   core 1.2.0 (dry-core)     both have ruby-core 0.7.1-1
#   types 1.2.2, 1.9.1        both have ruby-types 1.2.2-2 (Depends: ruby-core (>= 0.4.4))
#     (dry-types)
#   extra 1.0.0 needs mid; mid 1.0.0 needs core: both have ruby-extra 1.0-1
#                             (Depends: ruby-mid) and ruby-mid 1.0-1 (Depends: ruby-core)
#   plain: both have ruby-plain 2.0-1 (Depends: ruby-other), ruby-other 1.0-1; no .gem
#
# and newer versions that need a newer Ruby (their gemspec's
# required_ruby_version, also in the compact index): core 1.3.0 (>= 3.2),
# and types 2.0.0 (>= 3.3.1, as grape 4.1.0), which needs core ~> 1.3.
# bookworm's Ruby is 3.1.2, trixie's 3.3.8.
# late 2.0.0, the only version of late, needs Ruby >= 3.2: bookworm has
# ruby-late 1.0-1 (and in a second bookworm archive, bookworm-late, it
# depends on ruby-core), trixie none.
RSpec.describe "distribution gems that the release's own gems would shadow" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-shadowed-gems")
    builder = WorkspaceBuilder.new(File.join(@dir, "ws"))
    builder.package("tools/rest", type: :ruby, date: "2020-01-01T00:00:00Z", osdeps: %w[web web_logging late])
    builder.osdeps("web:\n  gem: web\nweb_logging:\n  gem: web_logging\nlate:\n  gem: late\n")
    builder.create
    gems = File.join(@dir, "server", "gems")
    GemBuilder.build(gems, "web", "4.1.0", dependencies: { "conf" => ">= 1.0", "types" => ">= 1.1", "extra" => ">= 0",
                                                           "plain" => ">= 1.0" })
    GemBuilder.build(gems, "web_logging", "3.0.1", dependencies: { "web" => ">= 2.0" })
    GemBuilder.build(gems, "conf", "1.4.0", dependencies: { "core" => "~> 1.0" })
    GemBuilder.build(gems, "core", "1.2.0")
    GemBuilder.build(gems, "core", "1.3.0", ruby: ">= 3.2")
    GemBuilder.build(gems, "types", "2.0.0", dependencies: { "core" => "~> 1.3" }, ruby: ">= 3.3.1")
    GemBuilder.build(gems, "types", "1.2.2", dependencies: { "core" => ">= 0.4" })
    GemBuilder.build(gems, "types", "1.9.1", dependencies: { "core" => "~> 1.0" })
    GemBuilder.build(gems, "extra", "1.0.0", dependencies: { "mid" => ">= 1.0" })
    GemBuilder.build(gems, "mid", "1.0.0", dependencies: { "core" => ">= 0.5" })
    GemBuilder.build(gems, "late", "2.0.0", ruby: ">= 3.2")
    GemBuilder.compact_index(File.join(@dir, "server"))
    @server = HttpServer.new(File.join(@dir, "server"))
    # an archive per codename: the same .deb names with other bytes would clash in one pool
    archives = { "bookworm" => "bookworm", "trixie" => "trixie", "bookworm-late" => "bookworm" }.to_h do |folder, codename|
      archive = AptRepositoryBuilder.new(File.join(@dir, folder), codenames: [codename], architectures: ["amd64"])
      archive.add_many([{ name: "ruby-conf", version: "0.9.0-2" }, { name: "ruby-core", version: "0.7.1-1" },
                        { name: "ruby-types", version: "1.2.2-2", depends: "ruby-core (>= 0.4.4)" },
                        { name: "ruby-extra", version: "1.0-1", depends: "ruby-mid" },
                        { name: "ruby-mid", version: "1.0-1", depends: "ruby-core | ruby-core-compat" },
                        { name: "ruby-plain", version: "2.0-1", depends: "ruby-other (>= 1.0), libc6" },
                        { name: "ruby-other", version: "1.0-1" }].map { |package| package.merge(arch: "amd64") },
                       codename: codename)
      [folder, archive]
    end
    archives.values_at("bookworm", "bookworm-late").each do |archive|
      archive.add("ruby-web", "1.6.2-3", codename: "bookworm", arch: "amd64", depends: "ruby-conf, ruby-types")
      archive.add("ruby-web-logging", "1.8.4-1", codename: "bookworm", arch: "amd64", depends: "ruby-web (>= 1.0)")
    end
    archives.fetch("bookworm").add("ruby-late", "1.0-1", codename: "bookworm", arch: "amd64")
    archives.fetch("bookworm-late").add("ruby-late", "1.0-1", codename: "bookworm", arch: "amd64", depends: "ruby-core")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rest.yml"),
               "release: rest\nworkspace: ../ws/workspace\ntargets: { bookworm: [amd64], trixie: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\ngem_source: #{@server.url}\nselect: [tools/rest]\n" \
               "distributions:\n  bookworm: { archive: { path: ../bookworm, trusted: true } }\n  " \
               "trixie: { archive: { path: ../trixie, trusted: true } }\n")
    @result = Relspec::Plan.run(File.join(@dir, "specs", "rest.yml"), cache_dir: nil)
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  def decisions(codename)
    @result.plan.targets.fetch(Relspec::Plan::Target.parse("#{codename}/amd64")).transform_values(&:to_h)
  end

  it "packages the distribution gem that depends on a packaged gem, at a version that fits every requirement" do
    %w[bookworm trixie].each do |codename|
      expect(decisions(codename)["types"])
        .to include("decision" => "build", "deb" => "rock-rest-ruby-types", "version" => "1.9.1-1~#{codename}",
                    "causes" => ["not taken from the distribution: ruby-types 1.2.2-2 (#{codename}) depends on core, " \
                                 "which the release packages at 1.2.0"])
      expect(decisions(codename)["core"]).to include("decision" => "build", "version" => "1.2.0-1~#{codename}")
    end
    # web's debian/ names the release's types, no longer Debian's ruby-types
    expect(@result.catalog.package("web").dependencies).to include("types")
    expect(@result.catalog.package("web").os_dependencies_for("trixie").gems).not_to include(a_string_starting_with("types"))
    expect(@result.plan.notes).to include("ruby-types 1.2.2-2 (bookworm) depends on core, which the release packages at " \
                                          "1.2.0: gem types is packaged here")
  end

  it "follows Debian's Depends through other gem packages, and packages what the walk reaches" do
    expect(decisions("trixie")["extra"])
      .to include("decision" => "build", "causes" => ["not taken from the distribution: ruby-extra 1.0-1 (trixie) depends " \
                                                      "on ruby-mid, which depends on core, which the release packages at 1.2.0"])
    expect(decisions("trixie")["mid"]).to include("decision" => "build", "version" => "1.0.0-1~trixie")
    # a distribution gem that reaches no packaged gem stays the distribution's
    expect(decisions("trixie").keys).not_to include("plain", "other")
    expect(@result.catalog.package("web").os_dependencies_for("trixie").gems).to include("plain>= 1.0")
  end

  it "does not take a gem of the release from a target's distribution whose package depends on one built there" do
    # bookworm's ruby-web 1.6.2 is too old for web_logging 3.0.1: web 4.1.0 is built there,
    # and Debian's ruby-web-logging 1.8.4 would run with it
    expect(decisions("bookworm")["web"]).to include("decision" => "build", "version" => "4.1.0-1~bookworm")
    expect(decisions("bookworm")["web_logging"])
      .to include("decision" => "build", "version" => "3.0.1-1~bookworm",
                  "causes" => ["not taken from the distribution: ruby-web-logging 1.8.4-1 (bookworm) depends on web, " \
                               "which the release packages at 4.1.0"])
  end

  it "says why with relspec why" do
    run = relspec("why", "specs/rest.yml", "types", "--target", "trixie/amd64", chdir: @dir, env: { "XDG_CACHE_HOME" => @dir })
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    expect(run.stdout).to eq("trixie/amd64: types is built here as rock-rest-ruby-types 1.9.1-1~trixie, because:\n  " \
                             "not taken from the distribution: ruby-types 1.2.2-2 (trixie) depends on core, which the " \
                             "release packages at 1.2.0\n")
  end

  # specs/<name>.yml: rest.yml as +change+ makes it, under another release name
  def spec_like_rest(name, change)
    File.write(File.join(@dir, "specs", "#{name}.yml"),
               change.call(File.read(File.join(@dir, "specs", "rest.yml")).sub("release: rest", "release: #{name}")))
    File.join(@dir, "specs", "#{name}.yml")
  end

  # A gem_source folder <name> with the server's .gem files but those +left_out+ matches.
  def gem_folder(name, left_out)
    folder = File.join(@dir, name)
    FileUtils.mkdir_p(folder)
    FileUtils.cp(Dir.glob(File.join(@dir, "server", "gems", "*.gem")).grep_v(left_out), folder)
    "../#{name}"
  end

  # relspec plan of specs/<name>.yml stops with one error and writes no lock: its stderr.
  def refused_plan(name)
    run = relspec("plan", "specs/#{name}.yml", chdir: @dir, env: { "XDG_CACHE_HOME" => @dir })
    expect(run.exit_code).to eq(1)
    expect(run.stderr.scan("error[").size).to eq(1)
    expect(run.stderr).not_to include("Traceback", ".rb:")
    expect(File.exist?(File.join(@dir, "releases", name, "lock.yml"))).to be(false)
    run.stderr
  end

  it "stops with one error saying why, when gem_source has no version of the gem it must package" do
    source = gem_folder("no-types-gems", %r{/types-})
    spec_like_rest("offline", ->(yaml) { yaml.sub(/^gem_source: .*$/, "gem_source: #{source}") })
    expect(refused_plan("offline"))
      .to include("error[gem-unresolvable]: no version of gem types in ../no-types-gems fits what is asked: gem web 4.1.0 " \
                  "(>= 1.1); it has none (not taken from the distribution: ruby-types 1.2.2-2 (bookworm) depends on core, " \
                  "which the release packages at 1.2.0)")
  end

  # core 1.3.0 and types 2.0.0 would install on bookworm but not load there
  it "packages the highest version every target's Ruby runs, and what it needs at versions that fit too" do
    %w[bookworm trixie].each do |codename|
      expect(decisions(codename)["types"]).to include("decision" => "build", "version" => "1.9.1-1~#{codename}")
      expect(decisions(codename)["core"]).to include("decision" => "build", "version" => "1.2.0-1~#{codename}")
    end
    expect(@result.catalog.package("types").version).to eq("1.9.1")
    # for trixie alone, the newest: one version serves every target of a spec
    trixie = spec_like_rest("trixie-only", ->(yaml) { yaml.sub(/^targets: .*$/, "targets: { trixie: [amd64] }") })
    decided = Relspec::Plan.run(trixie, cache_dir: nil).plan.targets.fetch(Relspec::Plan::Target.parse("trixie/amd64"))
    expect(decided.transform_values { |decision| decision.to_h["version"] }.slice("core", "types"))
      .to eq("core" => "1.3.0-1~trixie", "types" => "2.0.0-1~trixie")
  end

  it "takes the distribution's package on a target whose Ruby runs no version of the gem, and packages it for the others" do
    expect(decisions("bookworm")["late"]).to include("decision" => "system", "deb" => "ruby-late", "version" => "1.0-1")
    expect(decisions("trixie")["late"]).to include("decision" => "build", "version" => "2.0.0-1~trixie")
    expect(@result.plan.notes).to include("no version of gem late that fits runs on the Ruby of bookworm: taken from the " \
                                          "distribution there, packaged at 2.0.0 for the other targets")
  end

  it "stops when the distribution's package cannot be taken there after all (it depends on a gem the release builds)" do
    spec_like_rest("late-shadowed", ->(yaml) { yaml.sub("path: ../bookworm,", "path: ../bookworm-late,") })
    expect(refused_plan("late-shadowed"))
      .to include("specs/late-shadowed.yml:5:1: error[gem-ruby]: gem late 2.0.0 needs Ruby >= 3.2, and would be built for " \
                  "bookworm/amd64 (Ruby 3.1.2) (not taken from the distribution: ruby-late 1.0-1 (bookworm) depends on core, " \
                  "which the release packages at 1.2.0): it would install there but not load")
  end

  it "stops with one error naming the gem, the target and its Ruby, when no version runs there" do
    source = gem_folder("new-core-gems", %r{/core-1\.2\.0})
    spec_like_rest("new-core", ->(yaml) { yaml.sub(/^gem_source: .*$/, "gem_source: #{source}") })
    stderr = refused_plan("new-core")
    expect(stderr).to include("specs/new-core.yml:5:1: error[gem-ruby]: no version of gem core in ../new-core-gems that fits " \
                              "what is asked (gem conf 1.4.0 (~> 1.0)")
    expect(stderr).to include("runs on Ruby 3.1.2 (bookworm): 1.3.0 needs Ruby >= 3.2")
  end

  it "refuses a version of gems: that a target's Ruby cannot load, at its entry" do
    spec_like_rest("pinned-core", ->(yaml) { "#{yaml}gems: { core: 1.3.0 }\n" })
    expect(refused_plan("pinned-core"))
      .to include("specs/pinned-core.yml:10:15: error[gem-ruby]: gem core 1.3.0 of gems: needs Ruby >= 3.2, which Ruby 3.1.2 " \
                  "(bookworm) is not: it would install there but not load")
  end
end
