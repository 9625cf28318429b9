# frozen_string_literal: true

require "spec_helper"
require "json"
require "yaml"
require_relative "../../support/headless_chromium"

# The shipped example for real on this machine's distribution (bookworm/amd64):
# demo-base compiled, built (`relspec build --backend host`) and published; demo-child planned against
# that repository, so it builds only base/types and its reverse dependencies,
# built against demo-base's packages and published next to them. Then apt
# installs every package of demo-child (simulated, through a private apt
# configuration with both repositories and this machine's archive), and an
# installed demo-child package finds its inherited demo-base dependency
# through env.sh. The specs are the project's own, in a copy of the project.
# Then the field mirror of demo-child is made and proven; last, base/types is
# broken in the copy and demo-child built again: its status page, read by a
# real browser with the network cut.
#
# The shipped demo-base also targets trixie; its copy here is bookworm's
# alone (what this machine installs, runs and mirrors from its own archive).
# The two-distribution release is bin/demo's, spec/readme_spec.rb.
RSpec.describe "the example releases, built and published on bookworm", order: :defined do
  def target_name
    "bookworm/amd64"
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-example")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    %w[demo-base demo-child].each { |name| FileUtils.cp(File.join(CliRunner::ROOT, "specs", "#{name}.yml"), File.join(@dir, "specs")) }
    base = File.join(@dir, "specs", "demo-base.yml")
    shipped = File.read(base)
    raise "#{base}: no trixie target to leave out" unless shipped.include?("  trixie: [amd64]\n")

    File.write(base, shipped.sub("  trixie: [amd64]\n", ""))
    @workspace = DemoWorkspace.build(File.join(@dir, "examples"))
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def run!(*args)
    run = relspec(*args, chdir: @dir)
    raise "relspec #{args.join(' ')} failed: #{run.stderr}" unless run.status.success?

    run
  end

  def repository(release)
    File.join(@dir, "build", "repositories", release)
  end

  def osdeps(release)
    YAML.safe_load_file(File.join(repository(release), "osdeps", "#{release}-amd64.yml"))
  end

  def deb_names(release)
    osdeps(release).values.map { |entry| entry.fetch("debian").fetch("12,bookworm") }
  end

  # apt reads the repositories (updated into a private lists folder) and
  # this machine's archive (its sources and lists copied in: no network).
  # Not the machine's relspec-*.list nor lists of 127.0.0.1 repositories:
  # package_set_workspace_spec, in another process of bin/test, installs
  # demo-child from its own server meanwhile, and a run killed before its
  # clean-up leaves them (issue 46).
  def private_apt(dir)
    apt = PrivateApt.new(dir, %w[demo-base demo-child].map { |release| PrivateApt.source(repository(release), "bookworm") })
    output, status = apt.update
    raise output unless status.success?

    Dir.glob("/etc/apt/sources.list.d/*").reject { |file| File.basename(file).start_with?("relspec-") }
       .each { |file| FileUtils.cp(file, File.join(dir, "parts")) }
    Dir.glob("/var/lib/apt/lists/*_{Packages,InRelease,Release}*").reject { |file| File.basename(file).start_with?("127.0.0.1") }
       .each { |file| FileUtils.cp(file, File.join(dir, "lists")) }
    apt
  end

  it "builds only what demo-child changes, and apt installs all of demo-child" do
    run!("compile", "specs/demo-base.yml", "--out", "out")
    run!("build", "specs/demo-base.yml", "--out", "out", "--backend", "host", "--target", target_name)
    run!("publish", "specs/demo-base.yml", "--out", "out", "--target", target_name)
    expect(deb_names("demo-base").size).to eq(7)

    plan = JSON.parse(run!("plan", "specs/demo-child.yml", "--format", "json", "--target", target_name).stdout)
    decisions = plan.fetch("targets").fetch(target_name).transform_values { |entry| entry["decision"] }
    expect(decisions.select { |_, decision| decision == "build" }.keys)
      .to contain_exactly("base/types", "drivers/iodrivers_base", "tools/orocos.rb")
    expect(decisions.values.tally).to eq("build" => 3, "inherit" => 4)

    run!("compile", "specs/demo-child.yml", "--out", "out")
    run!("build", "specs/demo-child.yml", "--out", "out", "--backend", "host", "--target", target_name)
    publish = run!("publish", "specs/demo-child.yml", "--out", "out", "--target", target_name)
    # the status page is served with the repository
    expect(publish.stdout).to include("status page: #{File.join(repository('demo-child'), 'report', 'index.html')}")
    expect(File.read(File.join(repository("demo-child"), "report", "index.html"))).to include("<h1>Release demo-child</h1>")
    names = deb_names("demo-child")
    expect(names.grep(/\Arock-demo-child-/).size).to eq(3)
    expect(names.grep(/\Arock-demo-base-/).size).to eq(4)

    Dir.mktmpdir("relspec-apt") do |apt_dir|
      apt = private_apt(apt_dir)
      names.each do |name|
        output, status = apt.simulate(name)
        expect(status).to be_success, "#{name}: #{output}"
        expect(output).to match(/^Inst #{Regexp.escape(name)} /)
      end
    end

    # demo-child's driver, really installed (unpacked at /opt in a private
    # mount namespace), finds demo-base's logging through env.sh
    host = UnpackedRoot.new(File.join(@dir, "installed"))
    Dir.glob(File.join(@dir, "out", "demo-{base,child}", "*", "results", "*", "*.deb")).each { |deb| host.install(deb) }
    driver = "/opt/rock/demo-child/rock-demo-child-drivers-iodrivers-base"
    output, status = host.shell(". #{driver}/env.sh && echo \"$CMAKE_PREFIX_PATH\"")
    expect(status).to be_success, output
    expect(output.strip.split(":")).to include(driver, "/opt/rock/demo-base/rock-demo-base-base-logging",
                                               "/opt/rock/demo-child/rock-demo-child-base-types")
  end

  # The field mirror of demo-child (issue 35), made from the two
  # repositories the example above published and this machine's Debian
  # archive: its proofs pass (dose-debcheck; a clean system installed from
  # the mirror alone, no network, with all seven packages), a second run
  # changes nothing, and a .deb removed from the mirror is named by
  # `relspec mirror verify` with the packages that need it.
  it "mirrors demo-child with everything it needs, proven complete offline" do
    # the example above published both releases (order: :defined)
    expect(File).to be_directory(File.join(repository("demo-child"), "dists"))

    mirror = File.join(@dir, "mirror")
    run = relspec("mirror", "specs/demo-child.yml", "--out", mirror, "--format", "json", "--quiet", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    report = JSON.parse(run.stdout).fetch("targets").fetch("bookworm/amd64")
    expect(report.fetch("checks").transform_values { |check| check["status"] })
      .to eq("static" => "passed", "dynamic" => "passed")
    expect(report.fetch("packages")).to include("release" => 7, "inherited" => 4)
    expect(report.fetch("missing")).to eq([])
    expect(File.read(File.join(mirror, "VERIFIED.md"))).to include("## bookworm/amd64: complete")
    # the minimal system is in it: apt itself and the Essential packages
    packages = File.read(File.join(mirror, "dists", "bookworm", "main", "binary-amd64", "Packages"))
    expect(packages).to match(/^Package: apt$/).and match(/^Package: dpkg$/).and match(/^Package: rock-demo-base-base-logging$/)

    again = relspec("mirror", "specs/demo-child.yml", "--out", mirror, "--no-install", "--quiet", chdir: @dir)
    expect(again.exit_code).to eq(0), again.stderr
    expect(again.stdout).to include("changes: 0 added (0.0 MB), 0 removed, #{report['packages']['total']} kept")

    logging = Dir.glob(File.join(mirror, "pool", "**", "rock-demo-base-base-logging_*.deb")).first
    FileUtils.mv(logging, "#{logging}.away")
    verify = relspec("mirror", "verify", mirror, "--no-install", chdir: @dir)
    expect(verify.exit_code).to eq(1)
    expect(verify.stdout).to match(%r{missing: pool/\S+/rock-demo-base-base-logging_\S+\.deb \(rock-demo-base-base-logging \S+\) is missing \(needed by [^)]*rock-demo-child-drivers-iodrivers-base})
    expect(verify.stdout).to include("NOT complete")
  end

  # base/types's tag v2.0.0 (demo-child's pin) moved to a commit whose CMake
  # stops with a message in markup: the page must show it as text.
  def break_base_types
    source = @workspace.source_dir("base/types")
    File.write(File.join(source, "CMakeLists.txt"), "cmake_minimum_required(VERSION 3.10)\nproject(types NONE)\n" \
                                                    "message(FATAL_ERROR \"types <b>broken</b> & on purpose\")\n")
    @workspace.git(source, "add", "-A")
    @workspace.git(source, "commit", "-q", "-m", "Broken", date: "2020-07-01T00:00:00Z")
    @workspace.git(source, "tag", "-f", "v2.0.0")
  end

  # Every row of the page's package table: package => its cells' text.
  def rows(dom)
    dom[%r{<h2 id="packages">Packages</h2>.*?</table>}m].scan(%r{<tr><td>([^<]+)</td>(.*?)</tr>}m).to_h { |package, cells| [package, cells.gsub(/<[^>]+>/, " ").squeeze(" ").strip] }
  end

  it "writes a status page a browser shows offline: the failure, its log, what it blocks, what is inherited" do
    break_base_types
    run!("compile", "specs/demo-child.yml", "--out", "out")
    build = relspec("build", "specs/demo-child.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(build.exit_code).to eq(1), build.stdout + build.stderr
    page = File.join(@dir, "out", "demo-child", "report", "index.html")
    expect(run!("report", "specs/demo-child.yml", "--out", "out").stdout).to eq("wrote out/demo-child/report/index.html\n")
    first = File.binread(page)
    run!("report", "specs/demo-child.yml", "--out", "out")
    expect(File.binread(page)).to eq(first)

    # nothing to fetch: every link and source is on the page or next to it
    expect(first.scan(/(?:href|src)="([^"]*)"/).flatten).to all(match(%r{\A(#|logs/)}))
    expect(first).not_to match(/<script|<link|<img|@import|url\(/i)

    dom = HeadlessChromium.dump_dom(page)
    table = rows(dom)
    expect(table.fetch("base/types")).to include("built here", "failed")
    %w[drivers/iodrivers_base tools/orocos.rb].each do |package|
      expect(table.fetch(package)).to include("skipped because of base/types")
    end
    %w[base/cmake base/logging data/models tools/legacy].each do |package|
      expect(table.fetch(package)).to start_with("inherited from demo-base")
    end
    # the first error line, as text (the markup of the log is not the page's)
    expect(dom).to include("CMake Error at CMakeLists.txt:3 (message):\ntypes &lt;b&gt;broken&lt;/b&gt; &amp; on purpose")
    log = dom[/<a href="([^"]+)">whole log</, 1]
    expect(File.read(File.join(File.dirname(page), log))).to include("types <b>broken</b> & on purpose")
    expect(dom).to match(%r{<li><b>base/types</b> blocks 2 packages: drivers/iodrivers_base, tools/orocos.rb</li>})

    artefacts = ENV.fetch("RELSPEC_TEST_ARTEFACTS", File.join(CliRunner::ROOT, "tmp", "artefacts"))
    FileUtils.mkdir_p(artefacts)
    HeadlessChromium.screenshot(page, File.join(artefacts, "report-phone.png"), width: 412, height: 1900)
  end
end
