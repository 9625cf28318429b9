# frozen_string_literal: true

require "spec_helper"
require "webrick"
require_relative "../../support/demo_workspace"
require_relative "../../support/git_project"
require_relative "../../support/machine_apt"
require_relative "../../support/signing_key"

# The user's side, for real: the demo releases are built (host backend),
# published (demo-base signed, demo-child `trusted: true`) and served over
# HTTP on 127.0.0.1; `relspec osdeps package-set` makes the package set; an
# autoproj workspace (the demo workspace; package sets as local git
# repositories) adds it to its manifest, chooses demo-child, and real autoproj
# 2.18 installs the release with apt on this machine and builds. Needs root
# (apt installs into this machine, as the user's autoproj would, through
# sudo); MachineApt puts back exactly what it changed (packages, apt sources,
# keys and lists), and names plainly what it found that is not its own.
RSpec.describe "an autoproj workspace using relspec's package set" do
  RELEASE_DEBS = %w[rock-demo-base-base-cmake rock-demo-base-base-logging rock-demo-base-data-models
                    rock-demo-base-tools-legacy rock-demo-child-base-types rock-demo-child-drivers-iodrivers-base
                    rock-demo-child-ruby-tools-orocos.rb].freeze
  SOURCE_LISTS = %w[demo-base demo-child].to_h { |release| [release, "/etc/apt/sources.list.d/relspec-#{release}.list"] }

  before(:all) do
    raise "this test installs packages with apt on this machine: run it as root (CI does)" unless Process.uid.zero?

    @dir = Dir.mktmpdir("relspec-user")
    @gnupg = File.join(@dir, "gnupg")
    Dir.mkdir(@gnupg, 0o700)
    @key = SigningKey.new(@gnupg)
    @repos = File.join(@dir, "repos")
    FileUtils.mkdir_p(@repos)
    @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: 0, DocumentRoot: @repos,
                                      Logger: WEBrick::Log.new(File::NULL), AccessLog: [])
    @server_thread = Thread.new { @server.start }
    @url = "http://127.0.0.1:#{@server.config[:Port]}"
    @workspace = DemoWorkspace.build(File.join(@dir, "ws")).root
    write_specs
    %w[demo-base demo-child].each do |release|
      run!("compile", "specs/#{release}.yml")
      run!("build", "specs/#{release}.yml", "--backend", "host", "--jobs", "2")
      run!("publish", "specs/#{release}.yml")
    end
    run!("osdeps", "package-set", "--out", "package-set")
    GitProject.init(File.join(@dir, "package-set"))
    GitProject.commit_all(File.join(@dir, "package-set"), "relspec's package set")
    add_package_set
    @machine = MachineApt.new("rock-demo-*")
  end

  after(:all) do
    @machine&.restore
    @server&.shutdown
    @server_thread&.join(5)
    @key&.stop
    FileUtils.rm_rf(@dir) if @dir
  end

  # The demo specs as they are, but reading this test's workspace, published
  # into this test's folder, served by this test's server, demo-base signed.
  def write_specs
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    FileUtils.mkdir_p(File.join(@dir, "keys"))
    File.binwrite(File.join(@dir, "keys", "demo-base.gpg"), @key.public_keyring)
    %w[demo-base demo-child].each do |release|
      text = File.read(File.join(CliRunner::ROOT, "specs", "#{release}.yml"))
      edited = text.sub("workspace: ../examples/workspace", "workspace: ../ws/workspace")
                   .sub("path: ../build/repositories/", "path: ../repos/").gsub("http://127.0.0.1:8000", @url)
      edited = edited.sub(/^  trusted: true.*$/, "  sign_with: #{@key.fingerprint}\n  keyring: ../keys/demo-base.gpg") if release == "demo-base"
      expected = ["workspace: ../ws/workspace", "path: ../repos/", @url]
      expected << "keyring: ../keys/demo-base.gpg" if release == "demo-base"
      missing = expected.reject { |line| edited.include?(line) }
      raise "specs/#{release}.yml changed shape, the test cannot point it here: #{missing}" unless missing.empty?

      File.write(File.join(@dir, "specs", "#{release}.yml"), edited)
    end
  end

  # The user's first step: the package set in the manifest (a git
  # repository, as users get it). `ruby31: ignore` stands for what Rock's
  # own package sets define (the `ruby` osdep of tools/orocos.rb's manifest,
  # which autoproj aliases to ruby31), and the gems path for what
  # autoproj's bootstrap writes.
  def add_package_set
    manifest = File.join(@workspace, "autoproj", "manifest")
    data = YAML.safe_load(File.read(manifest))
    data["package_sets"] << { "type" => "git", "url" => File.join(@dir, "package-set") }
    File.write(manifest, YAML.dump(data))
    # nokogiri (a dependency of tools/orocos.rb, a gem in the demo's osdeps)
    # from Debian, since this test runs offline: as the release's packages get it
    File.write(File.join(@workspace, "autoproj", "ruby.osdeps"),
               "ruby: ignore\nruby31: ignore\nnokogiri:\n  debian: ruby-nokogiri\n")
    File.write(File.join(@workspace, ".autoproj", "config.yml"),
               "gems_install_path: #{File.join(@dir, 'gems')}\n", mode: "a")
    # the user's second step
    File.write(File.join(@workspace, "autoproj", "relspec.yml"), "release: demo-child\n")
  end

  def run!(*args)
    run = relspec(*args, chdir: @dir, env: @key.env)
    raise "relspec #{args.join(' ')}: #{run.stdout}#{run.stderr}" unless run.status.success?

    run
  end

  # Real autoproj, outside relspec's bundle, as the user runs it; git (its
  # importer) may only read local repositories.
  def autoproj(*args, env: {})
    env = env.merge("HOME" => File.join(@dir, "home"), "GIT_ALLOW_PROTOCOL" => "file", "GIT_CONFIG_NOSYSTEM" => "1")
    Bundler.with_unbundled_env do
      Open3.capture2e(env, RbConfig.ruby, Gem.bin_path("autoproj", "autoproj"), *args, chdir: @workspace, stdin_data: "")
    end
  end

  def autoproj!(*args)
    output, status = autoproj(*args)
    return output if status.success?

    lists = Dir.glob("/var/lib/apt/lists/127.0.0.1*").map { |path| File.basename(path) }
    sources = SOURCE_LISTS.values.map { |path| "#{path}: #{File.exist?(path) && File.read(path)}" }.join("\n")
    raise "autoproj #{args.join(' ')} failed:\n#{output}\n#{sources}\napt lists of 127.0.0.1: #{lists}"
  end

  def blacklist(entries)
    path = File.join(@workspace, "autoproj", "deb_blacklist.yml")
    entries ? File.write(path, YAML.dump(entries)) : FileUtils.rm_f(path)
  end

  def built_from_source
    Dir.glob("**/build/CMakeCache.txt", base: File.join(@workspace, "src")).map { |path| path.delete_suffix("/build/CMakeCache.txt") }.sort
  end

  it "installs every demo-child package with apt, the inherited ones from demo-base's repository, and builds nothing" do
    blacklist(nil)
    autoproj!("osdeps")
    expect(@machine.installed).to eq(RELEASE_DEBS)
    expect(SOURCE_LISTS.transform_values { |path| File.read(path) }).to eq(
      "demo-base" => "# written by relspec's autoproj package set\n" \
                     "deb [signed-by=/etc/apt/keyrings/relspec-demo-base.gpg] #{@url}/demo-base bookworm main\n",
      "demo-child" => "# written by relspec's autoproj package set\ndeb [trusted=yes] #{@url}/demo-child bookworm main\n"
    )
    # apt took base/cmake from demo-base's repository
    policy, = Open3.capture2("apt-cache", "policy", "rock-demo-base-base-cmake")
    expect(policy).to include("#{@url}/demo-base bookworm/main amd64 Packages")

    expect(autoproj!("show", "base/types")).not_to include("source package base/types")
    build = autoproj!("build")
    expect(build).to include("relspec: demo-child for debian 12,bookworm (amd64): 7 binary packages, 0 built from source")
    expect(build).not_to match(/building|configuring/)
    expect(built_from_source).to eq([])
    # nothing of the package set's checkout changed but its state folder
    checkout = Dir.glob(File.join(@workspace, ".autoproj", "remotes", "*")).first
    expect(GitProject.git(checkout, "status", "--porcelain", "--ignored")).to eq("!! state/\n")
  end

  it "builds a blacklisted package and its reverse dependencies from source against the binary rest" do
    blacklist(["base/types"])
    autoproj!("osdeps")
    output = autoproj!("build")
    expect(output).to include("4 binary packages, 3 built from source")
    expect(built_from_source).to eq(%w[base/types drivers/iodrivers_base])
    # autobuild prints "setting up …" and, unless its progress display folds
    # it away (seen in a CI run), "set up …"
    expect(output).to match(%r{set(ting)? up Ruby package tools/orocos\.rb})
    # the binaries' environment (their env.yml) reached autoproj's
    env = File.read(File.join(@workspace, "env.sh"))
    expect(env).to include("/opt/rock/demo-base/rock-demo-base-base-cmake")
    expect(env).to include("/opt/rock/demo-base/rock-demo-base-base-logging")
    expect(env).not_to include("rock-demo-child-base-types")
  ensure
    blacklist(nil)
    # what it built from source would otherwise count as built by the
    # example that expects nothing built, when that one runs later
    built_from_source.each { |name| FileUtils.rm_rf(File.join(@workspace, "src", name, "build")) }
  end

  it "refuses a tampered Release of the signed repository (apt checks it against the shipped key)" do
    autoproj!("osdeps")
    in_release = File.join(@repos, "demo-base", "dists", "bookworm", "InRelease")
    original = File.binread(in_release)
    File.binwrite(in_release, original.sub("Codename: bookworm", "Codename: bookworn"))
    FileUtils.rm_f(SOURCE_LISTS.values) # a machine that has not seen the release yet
    output, status = autoproj("osdeps")
    expect(status.success?).to be(false)
    expect(output).to include("relspec package set: timeout 300 apt-get update")
    expect(output).to include("The following signatures were invalid: BADSIG")
    # the failed update is tried again by the next run, which succeeds
    # once the repository is right again
    File.binwrite(in_release, original)
    autoproj!("osdeps")
  ensure
    File.binwrite(in_release, original) if original
  end

  # The maintainer republishes tools/legacy (a new commit, compiled, built
  # and published into demo-base's repository; the package set does not
  # change): the user's next `autoproj update` refreshes apt's lists of the
  # release, and `autoproj osdeps` installs the new version.
  it "brings a republished package with autoproj update and autoproj osdeps" do
    autoproj!("osdeps")
    before = installed_version("rock-demo-base-tools-legacy")
    upstream = File.join(@workspace, "repositories", "tools", "legacy.git")
    File.write(File.join(upstream, "NEWS"), "republished\n")
    GitProject.commit_all(upstream, "tools/legacy: NEWS")
    GitProject.git(File.join(@workspace, "src", "tools", "legacy"), "pull", "--quiet", "--ff-only", "autobuild", "master")
    # the maintainer's workspace: this one without the users' package set
    manifest = File.join(@workspace, "autoproj", "manifest")
    users = File.read(manifest)
    data = YAML.safe_load(users)
    data["package_sets"].pop
    File.write(manifest, YAML.dump(data))
    %w[compile build publish].each do |command|
      run!(command, "specs/demo-base.yml", *(command == "build" ? %w[--backend host --jobs 2] : []))
    end
    File.write(manifest, users)
    packages = File.read(File.join(@repos, "demo-base", "dists", "bookworm", "main", "binary-amd64", "Packages"))
    expect(packages[/^Package: rock-demo-base-tools-legacy\n(?:.+\n)*?Version: (.*)$/, 1]).to include("20210101")
    # --no-bundler --no-autoproj: this workspace was not made by autoproj's
    # bootstrap, which the update of autoproj itself needs
    update = autoproj!("update", "--no-bundler", "--no-autoproj")
    expect(update).to include("relspec: apt-get update for #{SOURCE_LISTS['demo-base']}")
    expect(update).to include("relspec: apt-get install --only-upgrade for 7 packages")
    autoproj!("osdeps")
    expect(installed_version("rock-demo-base-tools-legacy")).not_to eq(before)
    expect(installed_version("rock-demo-base-tools-legacy")).to include("20210101")
  ensure
    File.write(manifest, users) if users
  end

  def installed_version(deb)
    Open3.capture2("dpkg-query", "-W", "-f", "${Version}", deb).first
  end

  # Another workspace of the machine on demo-base (this workspace switched
  # to it, as that one would choose it): its source is demo-base's own
  # file, the one demo-child's workspace shares; demo-child's stays.
  it "lets workspaces on different releases share the machine" do
    autoproj!("osdeps")
    child = SOURCE_LISTS.transform_values { |path| File.read(path) }
    checkout = Dir.glob(File.join(@workspace, ".autoproj", "remotes", "*")).first
    # each apt-get update of a release rewrites its marker
    markers = -> { %w[demo-base demo-child].map { |release| File.mtime(File.join(checkout, "state", "apt", release)) } }
    updated = markers.call
    relspec_yml = File.join(@workspace, "autoproj", "relspec.yml")
    File.write(relspec_yml, "release: demo-base\n")
    autoproj!("show", "base/types") # init.rb runs; nothing is installed
    expect(File.read(File.join(checkout, "state", "release"))).to eq("demo-base\n")
    expect(SOURCE_LISTS.transform_values { |path| File.read(path) }).to eq(child)
    File.write(relspec_yml, "release: demo-child\n")
    autoproj!("show", "base/types")
    expect(markers.call).to eq(updated) # nothing new for apt: no apt-get update
  ensure
    File.write(relspec_yml, "release: demo-child\n") if relspec_yml
  end

  # docs/releasing.md's removal, run as written there; then the machine is
  # one that never saw the releases, and a first run while the repository
  # server is down (here: its folder is gone, apt gets 404) once left the
  # workspace stuck with "Unable to locate package" until a manual apt-get
  # update (issue 33): the next run, with the server back, installs.
  it "is removed by the documented commands, leaving /etc/apt as before; a first run with the server down is retried" do
    autoproj!("osdeps")
    expect(@machine.installed).to eq(RELEASE_DEBS)
    script = File.read(File.join(CliRunner::ROOT, "docs", "releasing.md"))[/<!-- removal -->\n```sh\n(.*?)```/m, 1]
    output, status = Open3.capture2e("bash", "-euc", script, chdir: @workspace)
    expect(status.success?).to be(true), output
    expect(@machine.installed).to eq([])
    # the documented removal deletes every relspec-*.list: one the test
    # found (MachineApt#note named it) is put back by MachineApt#restore
    expect(@machine.unexplained_changes).to eq([])

    FileUtils.mv(File.join(@repos, "demo-child"), File.join(@repos, "demo-child.down"))
    output, status = autoproj("osdeps")
    expect(status.success?).to be(false)
    expect(output).to include("relspec package set: timeout 300 apt-get update -o Dir::Etc::sourcelist=#{SOURCE_LISTS['demo-child']}")
    expect(output).to include("the next autoproj run tries again")
    expect(@machine.installed).to eq([])
    FileUtils.mv(File.join(@repos, "demo-child.down"), File.join(@repos, "demo-child"))
    autoproj!("osdeps")
    expect(@machine.installed).to eq(RELEASE_DEBS)
  ensure
    FileUtils.mv(File.join(@repos, "demo-child.down"), File.join(@repos, "demo-child")) if File.exist?(File.join(@repos, "demo-child.down"))
  end

  it "stops with a clear message when autoproj/relspec.yml names a release the package set does not have" do
    relspec_yml = File.join(@workspace, "autoproj", "relspec.yml")
    File.write(relspec_yml, "release: demo-nope\n")
    output, status = autoproj("show", "base/types")
    expect(status.success?).to be(false)
    expect(output).to include("relspec package set: #{relspec_yml}: release: \"demo-nope\" is not a release of this " \
                              "package set, expected `release: <name>` (one of demo-base, demo-child)")
  ensure
    File.write(relspec_yml, "release: demo-child\n")
  end

  it "stops with a clear message when the release does not exist for this system" do
    config = File.join(@workspace, ".autoproj", "config.yml")
    saved = File.read(config)
    # autoproj keeps the system it detected; AUTOPROJ_OS makes it another one
    File.write(config, YAML.dump(YAML.safe_load(saved).except("operating_system")))
    output, status = autoproj("show", "base/types", env: { "AUTOPROJ_OS" => "debian:11,bullseye" })
    expect(status.success?).to be(false)
    # issue 46, case 16: the user chose demo-child; demo-base is the ancestor lacking the system
    expect(output).to include("relspec package set: the release demo-child does not exist for debian 11,bullseye (amd64): " \
                              "its ancestor demo-base is not built for it (demo-base is built for debian 12,bookworm; debian 13,trixie)")
  ensure
    File.write(config, saved) if saved
  end
end
