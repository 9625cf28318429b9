# frozen_string_literal: true

require "spec_helper"
require "digest"

# `relspec compile` on the demo workspace, through the CLI, checked with the
# real Debian tools: dpkg-source, dpkg-buildpackage, lintian.
RSpec.describe "relspec compile" do
  built = %w[base/types drivers/iodrivers_base tools/orocos.rb].freeze

  before(:all) do
    @dir = Dir.mktmpdir("relspec-compile")
    @fixture = ReleaseFixture.new(@dir)
    @fixture.repository("parent", [%w[bionic amd64], %w[buster amd64]], ReleaseFixture::LAYOUT.to_h { |name| [name, {}] })
    @fixture.spec("parent", "targets: { bionic: [amd64], buster: [amd64] }\nrepository: { path: ../repos/parent, trusted: true }\n" \
                            "maintainer: Demo Packaging <demo@example.org>\n")
    @fixture.spec("child", "parent: parent\nblacklist: [{ match: base/types, reason: new API }]\n" \
                           "repository: { path: ../repos/child, trusted: true }\n", workspace: :checkouts)
    @first = relspec("compile", "specs/child.yml", "--out", "out1", chdir: @dir)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def tree_digests(dir)
    Dir.glob("**/*", File::FNM_DOTMATCH, base: dir).sort.select { |p| File.file?(File.join(dir, p)) }
       .to_h { |path| [path, Digest::SHA256.file(File.join(dir, path)).hexdigest] }
  end

  def package_dir(out, target, package)
    File.join(@dir, out, "child", target, @fixture.deb("child", package))
  end

  def dsc(out, target, package)
    Dir.glob(File.join(package_dir(out, target, package), "*.dsc")).first
  end

  it "emits a source package for each build, and only for builds" do
    expect(@first.exit_code).to eq(0), @first.stderr
    %w[bionic-amd64 buster-amd64].each do |target|
      dirs = Dir.children(File.join(@dir, "out1", "child", target)).reject { |name| name.end_with?(".yml") }.sort
      expect(dirs).to eq(built.map { |package| @fixture.deb("child", package) }.sort)
      built.each do |package|
        files = Dir.children(package_dir("out1", target, package)).reject { |name| name.start_with?(".") }
        upstream = @fixture.version(package, "bionic").sub(/-1~bionic\z/, "")
        deb = @fixture.deb("child", package)
        expect(files.sort).to eq(["#{deb}_#{upstream}-1~#{target[/\A[a-z]+/]}.debian.tar.xz",
                                  "#{deb}_#{upstream}-1~#{target[/\A[a-z]+/]}.dsc", "#{deb}_#{upstream}.orig.tar.gz"])
      end
    end
  end

  it "emits packages that dpkg-source extracts and that build with dpkg-buildpackage" do
    Dir.mktmpdir("relspec-build") do |work|
      built.each do |package|
        output, status = Open3.capture2e("dpkg-source", "-x", dsc("out1", "bionic-amd64", package), chdir: work)
        expect(status).to be_success, output
      end
      %w[base/types drivers/iodrivers_base].each do |package|
        tree = Dir.glob(File.join(work, "#{@fixture.deb('child', package)}-*")).find { |path| File.directory?(path) }
        # -d: the build dependencies from the ancestors' repositories and the
        # distribution (boost) cannot be installed on this offline machine
        output, status = Open3.capture2e("dpkg-buildpackage", "-us", "-uc", "-b", "-d", chdir: tree)
        expect(status).to be_success, output.lines.last(20).join
      end
      deb = Dir.glob(File.join(work, "rock-child-drivers-iodrivers-base_*_amd64.deb")).first
      fields, = Open3.capture2("dpkg-deb", "-f", deb, "Depends")
      expect(fields).to include("rock-child-base-types (>= #{@fixture.version('base/types', 'bionic')})")
      expect(fields).to include("rock-parent-base-logging (>= #{@fixture.version('base/logging', 'bionic')})")
      expect(fields).not_to include("cmake")
      contents, = Open3.capture2("dpkg-deb", "-c", deb)
      expect(contents).to include("./opt/rock/child/rock-child-drivers-iodrivers-base/env.sh")
      expect(contents).to include("./opt/rock/child/rock-child-drivers-iodrivers-base/share/drivers-iodrivers_base/README")
    end
  end

  it "declares build dependencies on what is built here and inherited, with versions" do
    control = File.read(dsc("out1", "buster-amd64", "drivers/iodrivers_base"))
    build_depends = control[/^Build-Depends: (.*)$/, 1]
    # buster's debhelper is 12.1.1: compat 13 does not exist there
    expect(build_depends).to include("debhelper-compat (= 12)", "cmake",
                                     "rock-child-base-types (>= #{@fixture.version('base/types', 'buster')})",
                                     "libboost1.67-all-dev")
    expect(build_depends).not_to include("build-essential")
  end

  it "passes lintian without errors" do
    dscs = built.map { |package| dsc("out1", "bionic-amd64", package) }
    output, = Open3.capture2e("lintian", "--no-tag-display-limit", *dscs)
    expect(output.lines.grep(/^E: /)).to eq([])
  end

  it "gives byte-identical files in another folder, and the same orig tarball for every distribution" do
    second = relspec("compile", "specs/child.yml", "--out", "out2", chdir: @dir)
    expect(second.exit_code).to eq(0), second.stderr
    expect(tree_digests(File.join(@dir, "out2"))).to eq(tree_digests(File.join(@dir, "out1")))
    built.each do |package|
      origs = %w[bionic-amd64 buster-amd64].map do |target|
        Digest::SHA256.file(Dir.glob(File.join(package_dir("out1", target, package), "*.orig.tar.gz")).first).hexdigest
      end
      expect(origs.uniq.size).to eq(1)
    end
  end

  it "writes nothing when nothing changed" do
    before = tree_digests(File.join(@dir, "out1")).merge("lock" => Digest::SHA256.file(File.join(@dir, "releases/child/lock.yml")).hexdigest)
    mtimes = Dir.glob(File.join(@dir, "out1", "**", "*")).to_h { |path| [path, File.mtime(path)] }
    run = relspec("compile", "specs/child.yml", "--out", "out1", chdir: @dir)
    expect(run.stdout).to eq("child: nothing changed (6 source packages up to date)\n")
    expect(Dir.glob(File.join(@dir, "out1", "**", "*")).to_h { |path| [path, File.mtime(path)] }).to eq(mtimes)
    expect(tree_digests(File.join(@dir, "out1")).merge("lock" => Digest::SHA256.file(File.join(@dir, "releases/child/lock.yml")).hexdigest)).to eq(before)
  end

  it "lists the builds in dependency order in plan.yml" do
    plan = YAML.safe_load(File.read(File.join(@dir, "out1", "child", "bionic-amd64", "plan.yml")))
    expect(plan["builds"].map { |build| [build["package"], build["build_depends"]] }).to eq([
      ["base/types", []], ["drivers/iodrivers_base", ["rock-child-base-types"]], ["tools/orocos.rb", ["rock-child-base-types"]]
    ])
  end

  it "renders the release's osdeps files" do
    osdeps = YAML.safe_load(File.read(File.join(@dir, "releases", "child", "osdeps", "child-amd64.yml")))
    expect(osdeps["base/types"]["debian"]).to eq("10,buster" => "rock-child-base-types")
    expect(osdeps["base/cmake"]["debian"]).to eq("10,buster" => "rock-parent-base-cmake")
  end

  it "refuses a catalog snapshot: it has no checkouts" do
    @fixture.spec("snap", "parent: parent\nblacklist: [{ match: base/types, reason: x }]\n")
    run = relspec("compile", "specs/snap.yml", "--out", "out-snap", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to start_with("specs/snap.yml:2:12: error[snapshot-workspace]: compile needs the package checkouts")
  end
end

RSpec.describe "relspec compile of a selected metapackage" do
  it "emits a metapackage depending on the members, which builds and resolves through osdeps" do
    Dir.mktmpdir("relspec-meta") do |dir|
      fixture = ReleaseFixture.new(dir)
      fixture.standalone("meta", select: ["demo.core"], targets: "bionic: [amd64]")
      run = relspec("compile", "specs/meta.yml", "--out", "out", chdir: dir)
      expect(run.exit_code).to eq(0), run.stderr
      dsc = Dir.glob(File.join(dir, "out", "meta", "bionic-amd64", "rock-meta-meta-demo.core", "*.dsc")).first
      expect(File.basename(dsc)).to eq("rock-meta-meta-demo.core_0.20200605.164500-1~bionic.dsc")
      expect(File.read(dsc)).to include("Architecture: all")
      Dir.mktmpdir do |work|
        output, status = Open3.capture2e("dpkg-source", "-x", dsc, "meta", chdir: work)
        expect(status).to be_success, output
        output, status = Open3.capture2e("dpkg-buildpackage", "-us", "-uc", "-b", "-d", chdir: File.join(work, "meta"))
        expect(status).to be_success, output.lines.last(10).join
        deb = Dir.glob(File.join(work, "*.deb")).first
        depends, = Open3.capture2("dpkg-deb", "-f", deb, "Depends")
        expect(depends).to include("rock-meta-base-types (>= #{fixture.version('base/types', 'bionic')})",
                                   "rock-meta-ruby-tools-orocos.rb (>= ")
      end
      osdeps = YAML.safe_load(File.read(File.join(dir, "releases", "meta", "osdeps", "meta-amd64.yml")))
      expect(osdeps["demo.core"]).to eq("ubuntu,debian" => { "18.04,bionic,beaver" => "rock-meta-meta-demo.core" })
    end
  end
end

RSpec.describe "compile progress" do
  it "reports each emitted source package, and stays silent when stderr is not a terminal" do
    Dir.mktmpdir("relspec-progress") do |dir|
      fixture = ReleaseFixture.new(dir)
      fixture.standalone("prog", select: ["base/logging"], targets: "bionic: [amd64], buster: [amd64]")
      calls = []
      require "relspec/compile"
      Relspec::Compile.run(File.join(dir, "specs", "prog.yml"), out: File.join(dir, "out"),
                                                                progress: ->(done, total) { calls << [done, total] })
      expect(calls.sort).to eq([[1, 4], [2, 4], [3, 4], [4, 4]])
      run = relspec("compile", "specs/prog.yml", "--out", "out2", chdir: dir)
      expect(run.exit_code).to eq(0), run.stderr
      expect(run.stderr).to eq("")
    end
  end
end
