# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "support/autoproj_user_system"

# The README's first two commands are the newcomer's contract; CI runs the
# second one, so the two must not drift apart.
RSpec.describe "README" do
  readme = File.read(File.join(CliRunner::ROOT, "README.md"))
  commands = readme[/```sh\n(.*?)```/m, 1].lines.map(&:strip)

  it "opens with the example command and the test command" do
    expect(readme.index("```sh")).to be < readme.index("## ")
    expect(commands.size).to eq(2)
    expect(commands[1]).to eq("bin/setup && bundle exec rubocop && bin/test")
  end

  it "has CI run exactly the test command" do
    ci = File.read(File.join(CliRunner::ROOT, ".ci", "run"))
    expect(ci.lines.map(&:strip)).to include(commands[1])
  end

  it "names only relspec commands that exist, in the example command and bin/demo" do
    demo = File.readlines(File.join(CliRunner::ROOT, "bin", "demo")).reject { |line| line.start_with?("#") }.join
    used = "#{commands[0]}\n#{demo}".scan(/relspec (\w+)/).flatten.uniq
    expect(used).to include("plan")
    help = relspec("help").stdout
    used.each { |command| expect(help).to include("relspec #{command}") }
  end
end

RSpec.describe "the README's example command" do
  # One run from scratch: demo-base is compiled, built and published for
  # two distributions, bookworm (this machine's: host backend; the sbuild
  # backend has its own test, spec/relspec/builder/sbuild_spec.rb) and trixie
  # (in sbuild: its chroot made by mmdebstrap from deb.debian.org, as
  # bookworm's is for sbuild_spec; `relspec compile` checks trixie's OS
  # dependencies against the same archive); demo-child inherits from it on
  # each and builds only what it must.
  # releases/ is committed (DESIGN §2): the run must give exactly what is
  # committed — the lock identifies the ancestor by what it provides, not by
  # its freshly dated Release file. When the example changes, `bin/demo`
  # regenerates releases/ (commit it).
  before(:all) do
    %w[examples/workspace build/repositories build/demo-base build/demo-child].each do |dir|
      FileUtils.rm_rf(File.join(CliRunner::ROOT, dir))
    end
    @demo = Open3.capture2e({ "RELSPEC_DEMO_BACKEND" => "host" }, File.join(CliRunner::ROOT, "bin", "demo"))
  end

  it "builds and publishes both releases for bookworm and trixie for real and regenerates releases/ exactly as committed" do
    output, status = @demo
    expect(status).to be_success, output
    expect(output).to include("2 specs valid: specs/demo-base.yml specs/demo-child.yml")
    expect(output).to include('blacklisted by "base/types" (the project needs the 2020 types API)')
    expect(output).to include("depends on base/types, which is rebuilt because blacklisted by")
    pool = Dir.glob(File.join(CliRunner::ROOT, "build", "repositories", "*", "pool", "**", "*.deb"))
    child = pool.grep(%r{/demo-child/}).map { |deb| File.basename(deb).split("_").first }
    expect(child).to include("rock-demo-child-base-types")
    expect(child).not_to include("rock-demo-child-base-cmake") # inherited from demo-base
    expect(pool.grep(%r{/demo-base/}).map { |deb| File.basename(deb).split("_").first }).to include("rock-demo-base-base-cmake")
    expect_both_distributions

    diff, diff_status = Open3.capture2e("git", "-C", CliRunner::ROOT, "diff", "--exit-code", "--", "releases/")
    expect(diff_status).to be_success, "releases/ differs from what is committed (run bin/demo and commit):\n#{diff}"
    untracked, = Open3.capture2e("git", "-C", CliRunner::ROOT, "status", "--porcelain", "--", "releases/")
    expect(untracked).to eq("")
    check = relspec("plan", "--check")
    expect([check.stdout, check.exit_code]).to eq(["", 0])
  end

  # The user's side on trixie, for real (bookworm's runs on this machine:
  # spec/relspec/osdeps/package_set_workspace_spec.rb): a clean trixie
  # system (the chroot tarball the demo's trixie builds used, unpacked), in
  # which the user installs Ruby 3.3 with apt and autoproj with gem; the
  # example workspace with the demo's package set in its manifest and
  # demo-child chosen; the repositories served where the specs say users
  # read them. autoproj installs every package of the release from them at
  # its trixie version and builds nothing; the Ruby library of the release
  # loads with trixie's Ruby in the workspace's environment (`autoproj exec`,
  # env.sh's).
  it "is installed on trixie by real autoproj through relspec's package set, at trixie's versions, building nothing" do
    output, status = @demo
    expect(status).to be_success, output
    dir = Dir.mktmpdir("relspec-trixie-user")
    user = AutoprojUserSystem.new(File.join(CliRunner::CACHE, "relspec", "chroots", "trixie-amd64.tar.zst"), dir)
    server = demo_server
    user.install_autoproj(File.join(CliRunner::ROOT, "Gemfile.lock"))
    # what the user's Rock package sets define (the `ruby` osdep of
    # tools/orocos.rb's manifest, which autoproj aliases to ruby33, and
    # nokogiri), as package_set_workspace_spec's user has them
    user.add_workspace(File.join(CliRunner::ROOT, "examples", "workspace"), build_path("package-set"),
                       release: "demo-child", osdeps: "ruby: ignore\nruby33: ignore\nnokogiri:\n  debian: ruby-nokogiri\n")
    user.autoproj!("osdeps")
    versions = published("demo-base", "trixie").merge(published("demo-child", "trixie"))
    expect(user.installed("rock-demo-*")).to eq(DEMO_CHILD_DEBS.to_h { |name| [name, versions.fetch(name)] })
    expect(user.installed("rock-demo-*").values).to all(end_with("~trixie"))
    expect(File.read(user.system.path("etc/apt/sources.list.d/relspec-demo-child.list")))
      .to end_with("deb [trusted=yes] http://127.0.0.1:8000/demo-child trixie main\n")
    build = user.autoproj!("build")
    expect(build).to include("relspec: demo-child for debian 13,trixie (amd64): 7 binary packages, 0 built from source")
    expect(build).not_to match(/building|configuring/)
    expect(user.built_from_source).to eq([])
    # the workspace's environment (env.sh's) holds the release's RUBYLIB
    ruby = user.autoproj!("exec", "ruby", "-e", 'require "orocos"; puts RUBY_VERSION, $LOADED_FEATURES.grep(/orocos/)')
    expect(ruby.lines.map(&:chomp)).to match([start_with("3.3."),
                                              "/opt/rock/demo-child/rock-demo-child-ruby-tools-orocos.rb/lib/orocos.rb"])
  ensure
    server&.stop
    FileUtils.rm_rf(dir) if dir # the whole system: nothing of it stays, failed or not
  end

  # The packages a demo-child user installs: its own and the rest from demo-base.
  DEMO_CHILD_DEBS = %w[rock-demo-base-base-cmake rock-demo-base-base-logging rock-demo-base-data-models
                       rock-demo-base-tools-legacy rock-demo-child-base-types rock-demo-child-drivers-iodrivers-base
                       rock-demo-child-ruby-tools-orocos.rb].freeze

  # build/repositories at http://127.0.0.1:8000, where the specs (and so
  # the package set) say users read them.
  def demo_server
    HttpServer.new(build_path("repositories"), port: 8000)
  rescue Errno::EADDRINUSE
    raise "port 8000 of 127.0.0.1 is taken: the demo's package set sends users' apt there"
  end

  def build_path(*parts)
    File.join(CliRunner::ROOT, "build", *parts)
  end

  # Package => version of a repository's Packages index of +codename+.
  def published(release, codename)
    text = File.read(build_path("repositories", release, "dists", codename, "main", "binary-amd64", "Packages"))
    text.split("\n\n").to_h { |stanza| [stanza[/^Package: (\S+)$/, 1], stanza[/^Version: (\S+)$/, 1]] }
  end

  # One repository per release holds both codenames, each with its own
  # builds (~codename versions, trixie's made in its own chroot); the
  # package set hands each distribution's users their codename's packages;
  # the status page has a column per target.
  def expect_both_distributions
    { "demo-base" => 7, "demo-child" => 3 }.each do |release, built|
      %w[bookworm trixie].each do |codename|
        versions = published(release, codename)
        expect(versions.size).to eq(built), "#{release} #{codename}: #{versions}"
        expect(versions.values).to all(end_with("~#{codename}"))
        packages = YAML.safe_load_file(build_path("package-set", "data", "packages", release, codename, "amd64.yml"))
        expect(packages.keys).to match_array(versions.keys)
      end
      page = File.read(build_path("repositories", release, "report", "index.html"))
      expect(page).to include('id="target-bookworm-amd64"', 'id="target-trixie-amd64"')
    end
    trixie_log = File.read(build_path("demo-base", "trixie-amd64", "logs", "rock-demo-base-base-cmake.log"))
    # sbuild runs inside the layer over the chroot unpacked once (ChrootLayers)
    expect(trixie_log).to match(/^\$ .*\bsbuild --chroot-mode=unshare .*--dist=trixie /)
    osdeps = YAML.safe_load_file(File.join(CliRunner::ROOT, "releases", "demo-child", "osdeps", "demo-child-amd64.yml"))
    expect(osdeps.fetch("base/types")).to eq("debian" => { "12,bookworm" => "rock-demo-child-base-types",
                                                           "13,trixie" => "rock-demo-child-base-types" })
    expect(osdeps.fetch("base/cmake").fetch("debian").values.uniq).to eq(["rock-demo-base-base-cmake"])
  end
end
