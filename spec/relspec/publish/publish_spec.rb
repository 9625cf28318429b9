# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "relspec/publish"

# `relspec publish` end to end, with real parts: the demo workspace compiled
# by relspec, built by `relspec build --backend host` (dpkg-buildpackage),
# published into a fresh reprepro repository and read
# back by apt-get and by relspec's own planner.
RSpec.describe "relspec publish" do
  def target_name
    "bookworm/amd64"
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-publish")
    @fixture = ReleaseFixture.new(@dir)
    @fixture.spec("solo", <<~YAML, workspace: :checkouts)
      select: [base/logging]
      targets: { bookworm: [amd64] }
      maintainer: Demo <demo@example.org>
      repository: { path: ../repos/solo, trusted: true }
    YAML
    run = relspec("compile", "specs/solo.yml", "--out", "out", chdir: @dir)
    raise run.stderr unless run.status.success?

    build = relspec("build", "specs/solo.yml", "--out", "out", "--backend", "host", chdir: @dir)
    raise build.stdout + build.stderr unless build.status.success?

    @target_dir = File.join(@dir, "out", "solo", target_name.tr("/", "-"))
    @results = File.join(@target_dir, "build-results.yml")
    @pristine = File.read(@results)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  before do
    FileUtils.rm_rf(repository)
    File.write(@results, @pristine)
  end

  def repository
    File.join(@dir, "repos", "solo")
  end

  def publish(*args, env: {})
    relspec("publish", "specs/solo.yml", "--out", "out", *args, chdir: @dir, env: env)
  end

  def cmake
    @fixture.deb("solo", "base/cmake")
  end

  def logging
    @fixture.deb("solo", "base/logging")
  end

  # Every file of the repository but reprepro's database, with its digest.
  def repository_state
    Dir.glob("**/*", base: repository).sort.reject { |path| path.start_with?("db") || File.directory?(File.join(repository, path)) }
       .to_h { |path| [path, Digest::SHA256.file(File.join(repository, path)).hexdigest] }
  end

  def edit_results
    data = YAML.safe_load(File.read(@results))
    yield data
    File.write(@results, YAML.dump(data))
  end

  it "publishes every built package, and apt installs them from the repository" do
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("bookworm/amd64: 2 published, 0 already in the repository", "published #{cmake}")
    expect(File.read(File.join(repository, "conf", "distributions"))).to eq(<<~CONF)
      Codename: bookworm
      Suite: bookworm
      Label: solo
      Architectures: amd64 source
      Components: main
      Description: solo for bookworm
    CONF
    expect(File.read(File.join(repository, "conf", "options"))).to eq("waitforlock 30\n")
    expect(repository_state.keys).to include("dists/bookworm/main/source/Sources.gz",
                                             a_string_matching(%r{\Apool/main/r/#{cmake}/#{cmake}_.*\.dsc\z}),
                                             a_string_matching(%r{\Apool/main/r/#{logging}/#{logging}_.*_amd64\.deb\z}))
    expect(File.read(File.join(repository, "osdeps", "solo-amd64.yml"))).to eq(<<~YAML)
      ---
      base/cmake:
        debian:
          12,bookworm: #{cmake}
      base/logging:
        debian:
          12,bookworm: #{logging}
    YAML

    Dir.mktmpdir("relspec-apt") do |apt_dir|
      apt = PrivateApt.new(apt_dir, [PrivateApt.source(repository, "bookworm")])
      output, status = apt.update
      expect(status).to be_success, output
      output, status = apt.simulate(logging)
      expect(status).to be_success, output
      expect(output).to include("Inst #{cmake} ", "Inst #{logging} ")
    end

    # the release's own repository now holds what it built: a new plan says so
    run = relspec("plan", "specs/solo.yml", "--format", "json", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    decisions = JSON.parse(run.stdout).fetch("targets").fetch(target_name).transform_values { |entry| entry["decision"] }
    expect(decisions).to eq("base/cmake" => "published", "base/logging" => "published")
  end

  it "changes nothing when the same results are published twice" do
    expect(publish.exit_code).to eq(0)
    before = repository_state
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("0 published, 2 already in the repository", "osdeps unchanged")
    expect(repository_state).to eq(before)
  end

  it "never publishes a failed package, nor one skipped because of it" do
    edit_results do |data|
      data["packages"][cmake].merge!("status" => "failed", "reason" => "compiler error").delete("files")
      data["packages"][logging].merge!("status" => "skipped", "reason" => "needs #{cmake}").delete("files")
    end
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("0 published", "not published: #{cmake} (failed)", "not published: #{logging} (skipped)")
    expect(Dir.exist?(File.join(repository, "pool"))).to be(false)
    expect(run.stderr).to include("not in the repository yet, so not in its osdeps files: 2 planned packages (bookworm/amd64: 2)")
    expect(File.read(File.join(repository, "osdeps", "solo-amd64.yml"))).to eq("--- {}\n")
  end

  it "publishes only what the plan builds, though build-results.yml keeps a record of more" do
    plan = File.join(@target_dir, "plan.yml")
    pristine = File.read(plan)
    # the plan of a narrower selection (compile rewrote plan.yml); the build
    # results keep base/logging's record for when the selection widens again
    data = YAML.safe_load(pristine)
    data["builds"].reject! { |build| build["package"] == "base/logging" }
    File.write(plan, YAML.dump(data))
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("bookworm/amd64: 1 published", "published #{cmake}")
    expect(repository_state.keys.grep(/#{Regexp.escape(logging)}/)).to eq([])
  ensure
    File.write(plan, pristine)
  end

  it "describes on its page what the repository holds after an interrupted rebuild" do
    # base/logging's record is of an earlier version than the plan's: its
    # rebuild was interrupted, so it is not the release's and not published
    edit_results { |data| data["packages"][logging]["version"] = "0.1-1~bookworm" }
    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("bookworm/amd64: 1 published", "published #{cmake}")
    expect(repository_state.keys.grep(/#{Regexp.escape(logging)}/)).to eq([])
    report = relspec("report", "specs/solo.yml", "--out", "out", "--format", "json", chdir: @dir)
    expect(report.exit_code).to eq(0), report.stderr
    cells = JSON.parse(File.read(File.join(@dir, "out", "solo", "report", "report.json")))
                .fetch("targets").first.fetch("packages").transform_values { |cell| cell["status"] }
    expect(cells).to eq("base/cmake" => "built", "base/logging" => "not built yet")
    page = File.read(File.join(repository, "report", "index.html"))
    expect(page.scan("not built yet").size).to be >= 1
  end

  it "resolves its spec once and reads each target's build-results.yml once, handing that reading to its page" do
    allow(Relspec::ReleaseSpec).to receive(:resolve).and_call_original
    allow(Relspec::Builder::BuildResults).to receive(:read).and_call_original
    allow(Relspec::Builder::BuildResults).to receive(:load).and_call_original
    Relspec::Publish.run(File.join(@dir, "specs", "solo.yml"), out: File.join(@dir, "out"))
    expect(Relspec::ReleaseSpec).to have_received(:resolve).once
    expect(Relspec::Builder::BuildResults).to have_received(:read).once
    expect(Relspec::Builder::BuildResults).to have_received(:load).exactly(0).times
    expect(File.read(File.join(repository, "report", "index.html"))).to include("base/logging")
  end

  it "refuses a package whose built file changed since it was recorded, before touching the repository" do
    deb = Dir.glob(File.join(@target_dir, "results", cmake, "*.deb")).first
    original = File.binread(deb)
    File.binwrite(deb, "#{original}x")
    run = publish
    expect(run.exit_code).not_to eq(0)
    expect(run.stderr).to include("#{cmake} ", "cannot be published", "has changed since it was built")
    expect(run.stderr).not_to include(".rb:")
    expect(Dir.exist?(File.join(repository, "pool"))).to be(false)
  ensure
    File.binwrite(deb, original)
  end

  it "refuses a file the pool holds with other bytes, naming both, and includes nothing" do
    expect(publish.exit_code).to eq(0)
    before = repository_state
    deb = Dir.glob(File.join(@target_dir, "results", logging, "*.deb")).first
    original = File.binread(deb)
    File.binwrite(deb, "#{original}x")
    edit_results do |data|
      entry = data["packages"][logging]["files"].find { |file| file["name"].end_with?(".deb") }
      entry.merge!("sha256" => Digest::SHA256.file(deb).hexdigest, "size" => File.size(deb))
    end
    run = publish
    expect(run.exit_code).to eq(1), run.stderr
    expect(run.stderr).to include("already holds with other bytes", deb.delete_prefix("#{@dir}/"),
                                  File.join(repository, "pool", "main", "r", logging, File.basename(deb)))
    expect(repository_state).to eq(before)
  ensure
    File.binwrite(deb, original) if original
  end

  it "names file:line of a damaged build-results.yml and creates no repository" do
    File.write(@results, @pristine.sub("status: built", "status: done"))
    run = publish
    expect(run.exit_code).to eq(1)
    line = @pristine.lines.index { |l| l.include?("status: built") } + 1
    expect(run.stderr).to match(%r{out/solo/bookworm-amd64/build-results\.yml:#{line}:\d+: error\[build-results\]: .*status "done"})
    expect(run.stderr).not_to include(".rb:")
    expect(Dir.exist?(repository)).to be(false)
  end

  it "says which target was not built" do
    FileUtils.rm_f(@results)
    run = publish("--target", target_name)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("bookworm/amd64 of solo has not been built", "run relspec build")
    run = publish
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("nothing to publish")
  end

  it "keeps the repository whole when two publishers run at once" do
    runs = Array.new(2) { Thread.new { publish } }.map(&:value)
    runs.each { |run| expect(run.exit_code).to eq(0), run.stderr }
    # one included the packages, the other found them there: the lock
    # serialised them (without it both would see an empty repository)
    expect(runs.map { |run| run.stdout[/\d+ published, \d+ already/] }).to contain_exactly("2 published, 0 already",
                                                                                           "0 published, 2 already")
    %w[check checkpool].each do |command|
      output, status = Open3.capture2e("reprepro", "-b", repository, command)
      expect(status).to be_success, output
    end
    concurrent = repository_state
    FileUtils.rm_rf(repository)
    expect(publish.exit_code).to eq(0)
    expect(repository_state.keys).to eq(concurrent.keys)
  end

  it "finishes a publication interrupted after a source package was included" do
    expect(publish.exit_code).to eq(0)
    complete = repository_state
    FileUtils.rm_rf(repository)
    # what a publisher killed between reprepro's includedsc and includedeb leaves
    FileUtils.mkdir_p(File.join(repository, "conf"))
    Relspec::Reprepro::Config.new(label: "solo", description: "solo for %<codename>s", targets: [Relspec::Target.parse(target_name)],
                                  source: true).write(File.join(repository, "conf"))
    dsc = Dir.glob(File.join(@target_dir, cmake, "*.dsc")).first
    output, status = Open3.capture2e("reprepro", "-b", repository, "includedsc", "bookworm", dsc)
    expect(status).to be_success, output

    run = publish
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("1 published, 1 already in the repository")
    pool = ->(state) { state.select { |path, _| path.start_with?("pool/", "osdeps/") } }
    expect(pool.call(repository_state)).to eq(pool.call(complete))
    expect(repository_state.keys).to eq(complete.keys)
  end

  it "reports a reprepro failure as one message with the tool, its exit status and output" do
    deb = Dir.glob(File.join(@target_dir, "results", logging, "*.deb")).first
    original = File.binread(deb)
    File.binwrite(deb, "not a Debian package\n")
    edit_results do |data|
      entry = data["packages"][logging]["files"].find { |file| file["name"].end_with?(".deb") }
      entry.merge!("sha256" => Digest::SHA256.file(deb).hexdigest, "size" => File.size(deb))
    end
    run = publish
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to match(%r{reprepro includedeb failed \(exit status \d+\) in .*repos/solo:\n})
    expect(run.stderr).to include(File.basename(deb))
    expect(run.stderr).not_to include(".rb:")
  ensure
    File.binwrite(deb, original) if original
  end

  it "refuses a version lower than the one the repository holds, which reprepro skips saying nothing, and publishes nothing" do
    # the repository holds base/logging's .deb at a higher revision: the built one repacked by dpkg-deb
    deb = Dir.glob(File.join(@target_dir, "results", logging, "*.deb")).first
    FileUtils.mkdir_p(File.join(repository, "conf"))
    Relspec::Reprepro::Config.new(label: "solo", description: "solo for %<codename>s", targets: [Relspec::Target.parse(target_name)],
                                  source: true).write(File.join(repository, "conf"))
    higher = Dir.mktmpdir do |tmp|
      system("dpkg-deb", "-R", deb, File.join(tmp, "x"), exception: true)
      control = File.join(tmp, "x", "DEBIAN", "control")
      version = File.read(control)[/^Version: (\S+)$/, 1]
      raised = version.sub(/-(\d+)~/) { "-#{Regexp.last_match(1).to_i + 5}~" }
      File.write(control, File.read(control).sub("Version: #{version}\n", "Version: #{raised}\n"))
      system("dpkg-deb", "-b", File.join(tmp, "x"), File.join(tmp, "higher.deb"), out: File::NULL, exception: true)
      system("reprepro", "-b", repository, "includedeb", "bookworm", File.join(tmp, "higher.deb"), out: File::NULL, exception: true)
      raised
    end
    listing = -> { Open3.capture2("reprepro", "-b", repository, "list", "bookworm").first }
    before = listing.call

    run = publish
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("bookworm/amd64: reprepro did not take 1 file(s) of #{logging}, though it exited 0; " \
                                  "nothing was published", "#{File.basename(deb)}: it keeps #{logging} #{higher}\n",
                                  "reprepro never replaces a package by a lower version")
    expect(run.stderr).not_to include(".rb:")
    expect(listing.call).to eq(before)
    expect(before).to eq("bookworm|main|amd64: #{logging} #{higher}\n")
  end

  it "names the spec line when the release has no repository path" do
    @fixture.spec("bare", "targets: { bookworm: [amd64] }\nrepository: { url: https://example.org/bare, trusted: true }\n")
    run = relspec("publish", "specs/bare.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to match(%r{specs/bare\.yml:4:1: error\[publish-repository\]: release bare has no repository\.path})
  end
end
