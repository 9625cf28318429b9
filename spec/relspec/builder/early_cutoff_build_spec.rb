# frozen_string_literal: true

require "spec_helper"
require "json"
require "yaml"
require_relative "../../support/build_release"

# The early cutoff on a published release (docs/abi.md, "Early cutoff"):
# base/lib, a C library, and base/user, which includes its header and
# links it, built with the host backend and published into a real reprepro
# repository. A new version of base/lib from an overlay that changes a
# function body: `relspec plan` names base/user a candidate that keeps its
# published version, `relspec build` decides base/lib's interface
# unchanged against the build it replaces and keeps base/user unbuilt, and
# publish leaves its published build in place, the lock saying why. A
# change of base/user itself then builds it at the revision after the kept
# one; the spec's early_cutoff and --rebuild-dependents refuse the
# cutoff; a header change rebuilds it as before. One set-up, in order.
RSpec.describe "the early cutoff on a published release", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-cutoff")
    @release = BuildRelease.new(@dir, "ec")
    @release.package("base/lib", cmake: "enable_language(C)\nadd_library(cut SHARED cut.c)\n" \
                                        "install(TARGETS cut LIBRARY DESTINATION lib)\ninstall(FILES cut.h DESTINATION include)",
                                 files: { "cut.c" => "#include \"cut.h\"\nint cut_value(void) { return 42; }\n",
                                          "cut.h" => "int cut_value(void);\n" })
    @release.package("base/user", dependencies: ["base/lib"])
    @release.package("base/app", dependencies: ["base/user"])
    @release.compile(spec: "repository: { path: ../repos/ec, trusted: true }\n")
    run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    run!("publish", "specs/ec.yml", "--out", "out")
    @first = record("base/lib")
    @first_user = record("base/user")
    @first_app = record("base/app")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def run!(*args)
    run = relspec(*args, chdir: @dir)
    raise "relspec #{args.join(' ')}: #{run.stdout}#{run.stderr}" unless run.exit_code.zero?

    run
  end

  def record(package)
    YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][@release.source(package)]
  end

  # A new version of +package+ from an overlay file over the source.
  def change(path, content, package: "base/lib")
    @release.change(package, path, content)
  end

  # Debian name => version of the binary packages the repository holds.
  def published
    @release.published
  end

  def lock
    YAML.safe_load(File.read(File.join(@dir, "releases", "ec", "lock.yml")))
  end

  def build_and_publish(*options)
    run!("compile", "specs/ec.yml", "--out", "out")
    build = run!("build", "specs/ec.yml", "--out", "out", "--backend", "host", *options)
    run!("publish", "specs/ec.yml", "--out", "out")
    build
  end

  def revision(version)
    version[/-(\d+)~/, 1].to_i
  end

  it "records no verdict for a first build" do
    expect(@first).not_to have_key("interface")
  end

  it "names the dependent a candidate, keeps it unbuilt after a body change, and publishes the library alone" do
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 43; }\n")
    plan = run!("plan", "specs/ec.yml").stdout
    expect(plan).to match(%r{base/user +rock-ec-base-user \S+-2\n    missing in all ancestors\n    early cutoff candidate: \S+-1~bookworm stays if the interface of base/lib does not change\n})
    expect(plan).not_to match(%r{base/lib .*\n.*\n    early cutoff})
    why = run!("why", "specs/ec.yml", "base/user").stdout
    expect(why).to end_with("  missing in all ancestors\n  early cutoff candidate: #{@first_user['version']} stays if the " \
                            "interface of base/lib does not change\n")
    lock_before = lock

    run!("compile", "specs/ec.yml", "--out", "out")
    # the candidate's history does not move at compile time
    expect(lock["history"]).to eq(lock_before["history"].merge("bookworm/amd64" => lock["history"]["bookworm/amd64"]))
    expect(lock["history"]["bookworm/amd64"]["base/user"]).to eq(lock_before["history"]["bookworm/amd64"]["base/user"])
    build = run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    body = record("base/lib")
    expect(body["version"]).not_to eq(@first["version"])
    expect(body["interface"]).to include("against" => @first["version"], "verdict" => "unchanged", "changes" => [])
    expect(body["interface"]["compared"]).to be >= 3 # the header, the library, the copyright
    # plan.yml carries the candidate; the build keeps base/user's published version and does not build it
    entry = YAML.safe_load(File.read(File.join(@release.target_dir, "plan.yml")))["builds"].find do |build_entry|
      build_entry["package"] == "base/user"
    end
    user_first = @first_user["version"]
    lib = @release.source("base/lib")
    # no dependency of base/user is a candidate: kept, its debian/ is the one planned
    # and the version the repository holds of base/lib, which its kept build was made against
    expect(entry["cutoff"]).to eq("keeps" => user_first, "because" => [lib],
                                  "debian_digest" => lock["targets"]["bookworm/amd64"]["base/user"]["debian_digest"],
                                  "against" => { lib => @first["version"] })
    user = record("base/user")
    expect(user).to include("status" => "kept", "version" => entry["version"])
    expect(user["files"]).to eq(@first_user["files"]) # the kept build's: the next build is compared with them
    expect(user["cutoff"]).to eq("keeps" => user_first, "verdict" => "keep", "reason" => "the interface of #{lib} did not change",
                                 "evidence" => ["#{lib}: #{body['interface']['compared']} files compared with " \
                                                "#{@first['version']}, unchanged"])
    expect(build.stdout).to include("bookworm/amd64: 1 built, 2 kept, 0 already built, 0 failed, 0 skipped")
    # base/app, whose debian/ moved only with base/user's version: kept through the chain
    app = record("base/app")
    expect(app).to include("status" => "kept")
    expect(app["cutoff"]).to include("keeps" => @first_app["version"], "reason" => "the interface of rock-ec-base-user did not change")
    expect(app["cutoff"]["evidence"]).to eq(user["cutoff"]["evidence"] + ["rock-ec-base-user kept at #{user_first}"])
    expect(build.stdout).to match(/rock-ec-base-user +\S+ +kept +early cutoff: keeps #{Regexp.escape(user_first)}: the interface of #{lib} did not change/)
    expect(Dir.glob(File.join(@release.target_dir, "results", "rock-ec-base-user", "*_#{entry['version'].sub(/\A\d+:/, '')}_*.deb"))).to be_empty

    FileUtils.cp(File.join(@dir, "releases", "ec", "lock.yml"), File.join(@dir, "compiled-lock.yml"))
    run!("publish", "specs/ec.yml", "--out", "out")
    expect(published).to include(lib => body["version"], "rock-ec-base-user" => user_first,
                                 "rock-ec-base-app" => @first_app["version"])
    # the status page publish wrote, and the diff of the lock compile wrote against publish's
    expect(File.read(File.join(@dir, "repos", "ec", "report", "index.html")))
      .to include(">kept</span> <span class=\"muted\">kept at #{user_first}: the interface of #{lib} did not change (")
    diff = run!("diff", "compiled-lock.yml", "releases/ec/lock.yml").stdout
    expect(diff).to include("base/user: ", "kept at #{user_first}: the interface of #{lib} did not change (")
    # what publish wrote of base/user is what a plan makes now (base/lib's decision moves from build to published)
    planned = JSON.parse(run!("plan", "specs/ec.yml", "--format", "json").stdout)
    expect(planned["targets"]["bookworm/amd64"]["base/user"]).to eq(lock["targets"]["bookworm/amd64"]["base/user"])
    %w[base/user base/app].each do |package|
      expect(planned["history"]["bookworm/amd64"][package]).to eq(lock["history"]["bookworm/amd64"][package])
    end
    # base/app's history vouches for its kept version with base/user at the version base/user keeps
    expect(planned["targets"]["bookworm/amd64"]["base/app"]).to eq(lock["targets"]["bookworm/amd64"]["base/app"])
    expect(lock["targets"]["bookworm/amd64"]["base/app"]).to include("decision" => "published", "version" => @first_app["version"])
    user_lock = lock["targets"]["bookworm/amd64"]["base/user"]
    expect(user_lock).to include("decision" => "published", "version" => user_first)
    expect(user_lock["kept"]).to start_with("the interface of #{lib} did not change (#{lib}: ")
    expect(lock["history"]["bookworm/amd64"]["base/user"].values.last).to include("revision" => 1, "kept" => user_lock["kept"])
    why = run!("why", "specs/ec.yml", "base/user").stdout
    expect(why).to include("base/user is kept at #{user_first} as rock-ec-base-user: the interface of #{lib} did not change (#{lib}: ")
    expect(run!("plan", "specs/ec.yml").stdout).not_to include("rock-ec-base-user #{entry['version']}")
  end

  it "builds a later change of the kept dependent itself at the revision after the kept one" do
    kept = lock["targets"]["bookworm/amd64"]["base/user"]
    expect(kept).to include("decision" => "published", "kept" => a_string_starting_with("the interface of"))
    kept = kept["version"]
    change("extra.txt", "a change of base/user\n", package: "base/user")
    build_and_publish
    user = record("base/user")
    expect(user["status"]).to eq("built")
    # compared with the kept build, whose record the keep carried on
    expect(user["interface"]).to include("against" => kept, "verdict" => "changed")
    expect(user["interface"]["changes"]).to eq(["opt/rock/ec/rock-ec-base-user/share/base-user/extra.txt: added"])
    expect(record("base/app")["cutoff"]).to include("verdict" => "rebuild", "reason" => "the interface of rock-ec-base-user changed")
    expect(revision(user["version"])).to eq(revision(kept) + 1)
    expect(revision(user["version"])).to eq(2) # the compile-time -2 was never published: given now, to these bytes
    expect(published["rock-ec-base-user"]).to eq(user["version"])
    expect(lock["targets"]["bookworm/amd64"]["base/user"]).not_to have_key("kept")
  end

  it "builds the candidate when the spec turns the early cutoff off, giving its reason" do
    spec = File.read(@release.spec_path)
    File.write(@release.spec_path, "#{spec}early_cutoff: { enabled: false, reason: \"testing every dependent\" }\n")
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 44; }\n")
    build = build_and_publish
    File.write(@release.spec_path, spec)
    expect(record("base/user")).to include("status" => "built")
    expect(record("base/user")["cutoff"]).to include("verdict" => "rebuild",
                                                     "reason" => "the early cutoff is off for ec: testing every dependent")
    expect(build.stdout).to include("early cutoff: rebuilt: the early cutoff is off for ec: testing every dependent")
  end

  it "builds the candidate with --rebuild-dependents" do
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 45; }\n")
    build_and_publish("--rebuild-dependents")
    expect(record("base/user")).to include("status" => "built")
    expect(record("base/user")["cutoff"]).to include("verdict" => "rebuild", "reason" => "--rebuild-dependents: every candidate is built")
    expect(published["rock-ec-base-user"]).to eq(record("base/user")["version"])
  end

  # Issue 45: base/lib built at a new version and not published, then
  # built again: its verdict against the unpublished build says nothing
  # of the published one base/user's kept build was made against.
  it "rebuilds the candidate when its dependency was compared with a build the repository does not hold" do
    lib = @release.source("base/lib")
    held = published[lib]
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 47; }\n")
    run!("compile", "specs/ec.yml", "--out", "out")
    run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    unpublished = record("base/lib")["version"]
    expect(record("base/user")).to include("status" => "kept")
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 48; }\n")
    build = build_and_publish
    # the verdict itself says its baseline is not the published build
    expect(record("base/lib")["interface"]).to include("against" => unpublished, "verdict" => "unchanged", "held" => held)
    expect(build.stdout).to include("interface unchanged from #{unpublished} (unpublished: the repository holds #{held})")
    reason = "#{lib}'s new build was compared with #{unpublished}, not with #{held} that the repository holds " \
             "and the kept build was made against"
    expect(record("base/user")).to include("status" => "built")
    expect(record("base/user")["cutoff"]).to include("verdict" => "rebuild", "reason" => reason)
    expect(record("base/app")["cutoff"]).to include("verdict" => "rebuild", "reason" => reason)
    expect(build.stdout).to include("early cutoff: rebuilt: #{reason}")
    expect(published).to include(lib => record("base/lib")["version"], "rock-ec-base-user" => record("base/user")["version"])
  end

  # base/app changes itself while base/lib's body change would keep
  # base/user: base/app's debian/ names base/user's new version, so
  # base/user is built after all, first, and published at it.
  it "builds a kept candidate after all when a build of the run names its new version" do
    change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 46; }\n")
    change("app.txt", "a change of base/app\n", package: "base/app")
    build = build_and_publish
    user = record("base/user")
    expect(user["status"]).to eq("built")
    expect(user["cutoff"]).to include("verdict" => "rebuild",
                                      "reason" => "built after all: rock-ec-base-app is built in this run and names its new version")
    expect(record("base/app")["status"]).to eq("built")
    expect(build.stdout).to include("bookworm/amd64: 3 built, 0 already built, 0 failed, 0 skipped")
    expect(published).to include("rock-ec-base-user" => user["version"], "rock-ec-base-app" => record("base/app")["version"])
  end

  it "decides a header change changed the interface, naming the header, and rebuilds the candidate" do
    before = record("base/lib")
    published_user = record("base/user")["version"]
    change("cut.h", "int cut_value(void);\nint cut_other(void);\n")
    run!("compile", "specs/ec.yml", "--out", "out")
    build = run!("build", "specs/ec.yml", "--out", "out", "--backend", "host")
    header = record("base/lib")
    expect(header["interface"]).to include("against" => before["version"], "verdict" => "changed")
    expect(header["interface"]["changes"]).to eq(["opt/rock/ec/rock-ec-base-lib/include/cut.h: differs"])
    expect(build.stdout).to include("interface changed from #{before['version']}: opt/rock/ec/rock-ec-base-lib/include/cut.h: differs")
    expect(record("base/user")).to include("status" => "built")
    expect(revision(record("base/user")["version"])).to eq(revision(published_user) + 1)
    expect(record("base/user")["cutoff"]).to eq("keeps" => published_user, "verdict" => "rebuild",
                                                "reason" => "the interface of #{@release.source('base/lib')} changed")
    expect(build.stdout).to include("early cutoff: rebuilt: the interface of #{@release.source('base/lib')} changed")
  end

  # A build-results.yml is untrusted: a keep of a version the repository no
  # longer holds is refused before the repository is touched.
  it "refuses to publish a keep whose version the repository does not hold, and publishes nothing" do
    path = File.join(@release.target_dir, "build-results.yml")
    results = YAML.safe_load(File.read(path))
    user = results["packages"][@release.source("base/user")]
    user.replace(user.slice("package", "version", "dsc_sha256").merge(
                   "status" => "kept", "cutoff" => { "keeps" => @first_user["version"], "verdict" => "keep", "reason" => "forged" }
                 ))
    File.write(path, YAML.dump(results))
    before = published
    run = relspec("publish", "specs/ec.yml", "--out", "out", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to start_with("relspec: error: bookworm/amd64: rock-ec-base-user was kept at #{@first_user['version']} by the " \
                                     "early cutoff, but the repository holds #{before['rock-ec-base-user']}; build it: " \
                                     "relspec build --rebuild-dependents")
    expect(run.stderr).not_to include("from /")
    expect(published).to eq(before)
  end
end
