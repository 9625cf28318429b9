# frozen_string_literal: true

require "spec_helper"
require "yaml"

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
  it "builds and publishes both releases for bookworm and trixie for real and regenerates releases/ exactly as committed" do
    %w[examples/workspace build/repositories build/demo-base build/demo-child].each do |dir|
      FileUtils.rm_rf(File.join(CliRunner::ROOT, dir))
    end
    output, status = Open3.capture2e({ "RELSPEC_DEMO_BACKEND" => "host" }, File.join(CliRunner::ROOT, "bin", "demo"))
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
