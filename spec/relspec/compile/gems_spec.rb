# frozen_string_literal: true

require "spec_helper"
require "digest"
require "yaml"
require "relspec/plan"

# Third-party gems of `gems:`: real .gem files (built with `gem build`)
# served by a WEBrick server as a RubyGems-style source, a distribution
# archive (reprepro) that has one of them as ruby-*, and the emitted sources
# built with dpkg-buildpackage.
RSpec.describe "relspec compile with gems" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-gems")
    @fixture = ReleaseFixture.new(@dir)
    gems = File.join(@dir, "gem-server", "gems")
    # like the real nokogiri, its extconf.rb needs mini_portile2 at build time
    GemBuilder.build(gems, "nokogiri", "1.10.10", dependencies: { "mini_portile2" => "~> 2.4.0" }, executable: true,
                                                  extension: ["mini_portile2"])
    # files tar --exclude-vcs would drop; the gem is rebuilt from its file list
    GemBuilder.build(gems, "mini_portile2", "2.4.0", date: "2019-01-05",
                                                     files: { ".gitignore" => "tmp/\n", "build/notes.txt" => "notes\n" })
    GemBuilder.build(gems, "mini_portile2", "2.3.0")
    @server = HttpServer.new(File.join(@dir, "gem-server"))
    ubuntu = AptRepositoryBuilder.new(File.join(@dir, "repos", "ubuntu"), codenames: ["bionic"], architectures: ["amd64"])
    ubuntu.add("ruby-mini-portile2", "2.4.0-1", codename: "bionic", arch: "amd64")
    @fixture.spec("gemrel", <<~YAML, workspace: :checkouts)
      select: [tools/orocos.rb]
      targets: { bionic: [amd64], buster: [amd64] }
      maintainer: Demo <demo@example.org>
      gems: { nokogiri: "1.10.10", mini_portile2: "2.4.0" }
      gem_source: #{@server.url}
      distributions:
        bionic: { archive: { path: ../repos/ubuntu, trusted: true } }
    YAML
    # the stand-in bionic archive holds only ruby-* packages: no availability check
    @compile = relspec("compile", "specs/gemrel.yml", "--out", "out", "--no-check", chdir: @dir)
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  def package_dir(target, deb)
    File.join(@dir, "out", "gemrel", target, deb)
  end

  def file_in(target, deb, pattern)
    Dir.glob(File.join(package_dir(target, deb), pattern)).first
  end

  def control(target, deb)
    File.read(file_in(target, deb, "*.dsc"))
  end

  # The environment of a builder, not of this test run: under `bundle exec`
  # every ruby child (gem install's extconf.rb included) would see only the
  # test bundle's gems.
  OUTSIDE_BUNDLE = %w[RUBYOPT RUBYLIB BUNDLE_GEMFILE BUNDLER_SETUP BUNDLE_BIN_PATH BUNDLER_VERSION GEM_HOME GEM_PATH]
                   .to_h { |name| [name, nil] }.freeze

  let(:nokogiri) { "rock-gemrel-ruby-nokogiri" }
  let(:portile) { "rock-gemrel-ruby-mini-portile2" }

  it "packages the gems, except one the distribution has at that version" do
    expect(@compile.exit_code).to eq(0), @compile.stderr
    bionic = YAML.safe_load(File.read(File.join(@dir, "out", "gemrel", "bionic-amd64", "plan.yml")))["builds"]
    buster = YAML.safe_load(File.read(File.join(@dir, "out", "gemrel", "buster-amd64", "plan.yml")))["builds"]
    expect(bionic.map { |build| build["package"] }).to include("nokogiri", "tools/orocos.rb")
    expect(bionic.map { |build| build["package"] }).not_to include("mini_portile2")
    names = buster.map { |build| build["package"] }
    expect(names.index("mini_portile2")).to be < names.index("nokogiri")
    expect(buster.find { |build| build["package"] == "nokogiri" })
      .to include("version" => "1.10.10-1~buster", "build_depends" => [portile])

    lock = YAML.safe_load(File.read(File.join(@dir, "releases", "gemrel", "lock.yml")))
    expect(lock.dig("targets", "bionic/amd64", "mini_portile2"))
      .to eq("decision" => "system", "deb" => "ruby-mini-portile2", "version" => "2.4.0-1")
    expect(lock.dig("packages", "nokogiri")).to include(
      "url" => "#{@server.url}/gems/nokogiri-1.10.10.gem", "version" => "1.10.10",
      "commit" => Digest::SHA256.file(File.join(@dir, "gem-server", "gems", "nokogiri-1.10.10.gem")).hexdigest
    )
    expect(lock["notes"]).to include(a_string_including("gems are packaged here on buster: no distribution archive"))
  end

  it "declares dependencies on the gems: the release's own, or the distribution's" do
    on_bionic = control("bionic-amd64", nokogiri)
    expect(on_bionic).to include("Architecture: any")
    expect(on_bionic[/^Build-Depends: .*$/]).to include("ruby-dev", "ruby-mini-portile2 (>= 2.4.0-1)")
    expect(control("buster-amd64", nokogiri)[/^Build-Depends: .*$/]).to include("#{portile} (>= 2.4.0-1~buster)")
    expect(control("buster-amd64", portile)).to include("Architecture: all")

    tree = Dir.mktmpdir("relspec-gem-x")
    output, status = Open3.capture2e("dpkg-source", "-x", file_in("bionic-amd64", "rock-gemrel-ruby-tools-orocos.rb", "*.dsc"),
                                     "src", chdir: tree)
    expect(status).to be_success, output
    depends = File.read(File.join(tree, "src", "debian", "control"))[/^Depends:(.*?)\nDescription/m, 1]
    expect(depends).to include("#{nokogiri} (>= 1.10.10-1~bionic)")
    expect(depends).not_to match(/(^|\s)ruby-nokogiri/)
  ensure
    FileUtils.rm_rf(tree) if tree
  end

  it "makes one orig tarball per gem version: the unpacked gem, dated by the gem" do
    bionic = file_in("bionic-amd64", nokogiri, "*.orig.tar.gz")
    buster = file_in("buster-amd64", nokogiri, "*.orig.tar.gz")
    expect(File.basename(bionic)).to eq("#{nokogiri}_1.10.10.orig.tar.gz")
    expect(File.binread(bionic)).to eq(File.binread(buster))
    listing, = Open3.capture2("tar", "-tvzf", bionic)
    expect(listing).to include("#{nokogiri}-1.10.10/metadata.yml", "#{nokogiri}-1.10.10/lib/nokogiri.rb",
                               "#{nokogiri}-1.10.10/ext/nokogiri/extconf.rb")
    expect(listing.lines.map { |line| line.split[3] }.uniq).to eq(["2020-02-02"])
    expect(listing.lines.map { |line| line.split[1] }.uniq).to eq(["0/0"])
  end

  it "emits sources that build into gems installed under the release prefix, extension compiled" do
    expect(Process.uid).to eq(0), "this test installs a .deb: run it as root (CI does)"
    Dir.mktmpdir("relspec-gem-build") do |work|
      # mini_portile2 first, installed (as the builder would from its
      # repository), then nokogiri with its build dependencies checked: its
      # extconf.rb finds mini_portile2 in the release prefix through GEM_PATH
      [portile, nokogiri].each do |deb|
        output, status = Open3.capture2e("dpkg-source", "-x", file_in("buster-amd64", deb, "*.dsc"), deb, chdir: work)
        expect(status).to be_success, output
        output, status = Open3.capture2e(OUTSIDE_BUNDLE, "dpkg-buildpackage", "-us", "-uc", "-b", chdir: File.join(work, deb))
        expect(status).to be_success, output.lines.last(20).join
        next unless deb == portile

        output, status = Open3.capture2e("dpkg", "-i", Dir.glob(File.join(work, "#{portile}_*.deb")).first)
        expect(status).to be_success, output
      end
      deb = Dir.glob(File.join(work, "#{nokogiri}_1.10.10-1~buster_amd64.deb")).first
      expect(deb).not_to be_nil
      root = File.join(work, "root")
      system("dpkg-deb", "-x", deb, root, exception: true)
      system("dpkg-deb", "-x", Dir.glob(File.join(work, "#{portile}_2.4.0-1~buster_all.deb")).first, root, exception: true)
      prefix = File.join(root, "opt/rock/gemrel", nokogiri)
      expect(File).to exist(File.join(prefix, "gems/gems/nokogiri-1.10.10/lib/nokogiri.rb"))
      expect(Dir.glob(File.join(prefix, "gems/**/nokogiri_ext.so"))).not_to be_empty
      # with both gems' env.sh applied, as a user of the release would run it
      gem_path = [prefix, File.join(root, "opt/rock/gemrel", portile)].map { |dir| File.join(dir, "gems") }
      env = OUTSIDE_BUNDLE.merge("GEM_PATH" => gem_path.join(":"))
      output, status = Open3.capture2e(env, "ruby", "-e", 'require "nokogiri/nokogiri_ext"; print NokogiriExt.name')
      expect([output, status.success?]).to eq(["NokogiriExt", true])
      output, status = Open3.capture2e(env, "ruby", File.join(prefix, "bin", "nokogiri"))
      expect([output.strip, status.success?]).to eq(["nokogiri", true])
      fields, = Open3.capture2("dpkg-deb", "-f", deb, "Depends")
      expect(fields).to include("#{portile} (>= 2.4.0-1~buster)", "ruby")
      expect(fields).not_to include("ruby-dev")
      portile_contents, = Open3.capture2("dpkg-deb", "-c", Dir.glob(File.join(work, "#{portile}_*.deb")).first)
      expect(portile_contents).to include("gems/mini_portile2-2.4.0/.gitignore", "gems/mini_portile2-2.4.0/build/notes.txt")
    end
  ensure
    system("dpkg", "--purge", portile, out: File::NULL, err: File::NULL)
  end

  it "renders the gems into the osdeps files under the names that provide them" do
    osdeps = YAML.safe_load(File.read(File.join(@dir, "releases", "gemrel", "osdeps", "gemrel-amd64.yml")))
    expect(osdeps["mini_portile2"]).to eq("ubuntu,debian" => { "18.04,bionic,beaver" => "ruby-mini-portile2" },
                                          "debian" => { "10,buster" => portile })
    expect(osdeps["nokogiri"]).to eq("ubuntu,debian" => { "18.04,bionic,beaver" => nokogiri },
                                     "debian" => { "10,buster" => nokogiri })
  end

  it "keeps what the distribution provides in osdeps files rendered from the repositories" do
    run = relspec("osdeps", "specs/gemrel.yml", "--from-repository", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    osdeps = YAML.safe_load(File.read(File.join(@dir, "releases", "gemrel", "osdeps", "gemrel-amd64.yml")))
    # nothing of gemrel is published yet: only the distribution's package remains
    expect(osdeps).to eq("mini_portile2" => { "ubuntu,debian" => { "18.04,bionic,beaver" => "ruby-mini-portile2" } })
    expect(run.stderr).to include("missing from the repository: buster/amd64 mini_portile2")
    expect(run.stderr).not_to include("bionic/amd64 mini_portile2")
  ensure
    relspec("compile", "specs/gemrel.yml", "--out", "out", "--no-check", chdir: @dir) # the full osdeps files again
  end

  it "refuses a .gem that differs from the one the lock recorded for that version" do
    source = File.join(@dir, "changing-gems")
    GemBuilder.build(source, "mini_portile2", "2.4.0", date: "2019-01-05")
    spec = @fixture.spec("changing", "targets: { bionic: [amd64] }\nselect: [base/cmake]\n" \
                                     "gems: { mini_portile2: \"2.4.0\" }\ngem_source: ../changing-gems\n")
    expect(relspec("plan", spec, "--write", chdir: @dir).exit_code).to eq(0)
    GemBuilder.build(source, "mini_portile2", "2.4.0", date: "2019-01-06") # same version, other bytes
    run = relspec("plan", spec, "--write", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("specs/changing.yml:5:24: error[gem-changed]: gem mini_portile2 2.4.0 from " \
                                  "../changing-gems/mini_portile2-2.4.0.gem is not the .gem the lock recorded")
  end

  it "passes lintian without errors" do
    dscs = [file_in("buster-amd64", nokogiri, "*.dsc"), file_in("buster-amd64", portile, "*.dsc")]
    output, = Open3.capture2e("lintian", "--no-tag-display-limit", *dscs)
    expect(output.lines.grep(/^E:/)).to eq([])
  end

  it "writes nothing on a second compile" do
    again = relspec("compile", "specs/gemrel.yml", "--out", "out", "--no-check", chdir: @dir)
    expect(again.exit_code).to eq(0), again.stderr
    expect(again.stdout).to eq("gemrel: nothing changed (11 source packages up to date)\n")
  end

  it "inherits a gem an ancestor has at the same version, and rebuilds it at another" do
    builder = AptRepositoryBuilder.new(File.join(@dir, "repos", "gemparent2"), codenames: ["bionic"], architectures: ["amd64"])
    builder.add("rock-gemparent2-ruby-mini-portile2", "2.4.0-3~bionic", codename: "bionic", arch: "amd64")
    builder.add("rock-gemparent2-ruby-nokogiri", "1.10.9-1~bionic", codename: "bionic", arch: "amd64")
    @fixture.spec("gemparent2", "targets: { bionic: [amd64] }\nrepository: { path: ../repos/gemparent2, trusted: true }\n")
    path = File.join(@dir, @fixture.spec("gemchild", <<~YAML))
      parent: gemparent2
      select: [base/cmake]
      gems: { nokogiri: "1.10.10", mini_portile2: "2.4.0" }
      gem_source: ../gem-server/gems
    YAML
    plan = Relspec::Plan.run(path, cache_dir: nil).plan
    decisions = plan.targets.fetch(Relspec::Plan::Target.parse("bionic/amd64"))
    expect(decisions["mini_portile2"].to_h)
      .to eq("decision" => "inherit", "deb" => "rock-gemparent2-ruby-mini-portile2", "version" => "2.4.0-3~bionic",
             "from" => "gemparent2")
    expect(decisions["nokogiri"].to_h).to include("decision" => "build", "deb" => "rock-gemchild-ruby-nokogiri",
                                                  "version" => "1.10.10-1~bionic",
                                                  "causes" => ["gem version 1.10.10 (gemparent2 has 1.10.9)"])
  end

  it "refuses a gem the source does not have, and gems whose versions do not fit together" do
    @fixture.spec("nogem", <<~YAML)
      targets: { bionic: [amd64] }
      select: [base/cmake]
      gems:
        nokogiri: "1.10.10"
        mini_portile2: "9.9.9"
      gem_source: #{@server.url}
    YAML
    run = relspec("plan", "specs/nogem.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("specs/nogem.yml:7:18: error[gem-source]: #{@server.url}/gems/mini_portile2-9.9.9.gem " \
                                  "does not exist (HTTP 404)")
    expect(run.stderr).not_to include("Traceback", ".rb:")

    @fixture.spec("misfit", <<~YAML)
      targets: { bionic: [amd64] }
      select: [base/cmake]
      gems: { nokogiri: "1.10.10", mini_portile2: "2.3.0" }
      gem_source: ../gem-server/gems
    YAML
    run = relspec("plan", "specs/misfit.yml", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[gem-requirement]: gem nokogiri 1.10.10 needs mini_portile2 ~> 2.4.0, " \
                                  "the release packages mini_portile2 2.3.0")
  end
end
