# frozen_string_literal: true

require "spec_helper"
require "digest"

# Overlays and incremental compiles: changing one package regenerates only
# it, with the next revision.
RSpec.describe "relspec compile with overlays" do
  around do |example|
    Dir.mktmpdir("relspec-overlay") do |dir|
      @dir = dir
      @fixture = ReleaseFixture.new(dir)
      @fixture.repository("parent", [%w[bionic amd64]], ReleaseFixture::LAYOUT.to_h { |name| [name, {}] })
      @fixture.spec("parent", "targets: { bionic: [amd64] }\nrepository: { path: ../repos/parent, trusted: true }\n" \
                              "maintainer: Demo Packaging <demo@example.org>\n")
      @fixture.spec("child", "parent: parent\nblacklist: [{ match: base/types, reason: new API }]\n", workspace: :checkouts)
      example.run
    end
  end

  def compile
    relspec("compile", "specs/child.yml", "--out", "out", chdir: @dir)
  end

  def overlay(package, path, content)
    file = File.join(@dir, "overlays", package, path)
    FileUtils.mkdir_p(File.dirname(file))
    File.write(file, content)
  end

  def orocos_dir
    File.join(@dir, "out", "child", "bionic-amd64", "rock-child-ruby-tools-orocos.rb")
  end

  patch = <<~DIFF
    --- a/README
    +++ b/README
    @@ -1 +1,2 @@
     tools/orocos.rb: part of the relspec demo workspace.
    +patched by an overlay
  DIFF

  it "regenerates only the package whose overlay changed, with the next revision" do
    expect(compile.exit_code).to eq(0)
    others = Dir.glob(File.join(@dir, "out", "child", "bionic-amd64", "*", "*")).reject { |path| path.start_with?(orocos_dir) }
    mtimes = others.to_h { |path| [path, File.mtime(path)] }
    orig = -> { Digest::SHA256.file(Dir.glob(File.join(orocos_dir, "*.orig.tar.gz")).first).hexdigest }
    upstream_orig = orig.call
    overlay("tools/orocos.rb", "files/lib/extra.rb", "PREFIX = \"@RELSPEC_INSTALL_DIR@\"\n")
    overlay("tools/orocos.rb", "patches/01-readme.patch", patch)
    overlay("tools/orocos.rb", "debian/README.Debian", "Release @RELSPEC_RELEASE@, package @RELSPEC_PACKAGE@.\n")
    run = compile
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout.lines.grep(/^wrote /)).to eq(["wrote out/child/bionic-amd64/rock-child-ruby-tools-orocos.rb\n"])
    expect(others.to_h { |path| [path, File.mtime(path)] }).to eq(mtimes)
    expect(Dir.children(orocos_dir).grep(/\.dsc\z/).first).to end_with("-2~bionic.dsc")
    # the overlay's files travel in debian/: the orig tarball of the upstream version is unchanged
    expect(orig.call).to eq(upstream_orig)

    Dir.mktmpdir do |work|
      output, status = Open3.capture2e("dpkg-source", "-x", Dir.glob(File.join(orocos_dir, "*.dsc")).first, "tree", chdir: work)
      expect(status).to be_success, output
      tree = File.join(work, "tree")
      expect(File.read(File.join(tree, "lib", "extra.rb"))).to eq("PREFIX = \"/opt/rock/child/rock-child-ruby-tools-orocos.rb\"\n")
      expect(File.read(File.join(tree, "README"))).to end_with("patched by an overlay\n")
      expect(File.read(File.join(tree, "debian", "patches", "series"))).to eq("relspec-overlay-files.patch\n01-readme.patch\n")
      expect(File.read(File.join(tree, "debian", "patches", "relspec-overlay-files.patch")))
        .to include("--- /dev/null\n+++ b/lib/extra.rb\n@@ -0,0 +1,1 @@\n+PREFIX = ")
      expect(File.read(File.join(tree, "debian", "patches", "01-readme.patch"))).to start_with("Description: 01-readme.patch")
      expect(File.read(File.join(tree, "debian", "README.Debian"))).to eq("Release child, package rock-child-ruby-tools-orocos.rb.\n")
    end
  end

  it "names the patch and the package when a patch does not apply" do
    overlay("tools/orocos.rb", "patches/broken.patch", patch.sub("tools/orocos.rb: part", "something else"))
    run = compile
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[source-package]: dpkg-source failed for tools/orocos.rb (rock-child-ruby-tools-orocos.rb)")
    expect(run.stderr).to include("broken.patch")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(Dir.exist?(orocos_dir)).to be(false)
  end

  it "refuses links in overlays" do
    FileUtils.mkdir_p(File.join(@dir, "overlays", "tools", "orocos.rb", "files"))
    File.symlink("/etc/passwd", File.join(@dir, "overlays", "tools", "orocos.rb", "files", "passwd"))
    run = compile
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("error[overlay]: overlays may not contain links")
  end
end

# What a compiled target folder (out/<release>/<codename>-<arch>) holds.
module CompiledTarget
  # debian/NOTE of the newest debian.tar.xz there ("" when it has none)
  def debian_note(target_dir)
    tarball = Dir.glob(File.join(target_dir, "*", "*.debian.tar.xz")).max_by { |path| File.mtime(path) }
    IO.popen(["tar", "-xJOf", tarball, "debian/NOTE"], err: File::NULL, &:read)
  end

  def dsc_names(target_dir)
    Dir.glob(File.join(target_dir, "*", "*.dsc")).map { |path| File.basename(path) }.sort
  end

  # a project folder with specs/<release>.yml releasing base/cmake for +targets+
  def with_release(release, targets)
    Dir.mktmpdir("relspec-#{release}-overlay") do |dir|
      ReleaseFixture.new(dir).standalone(release, select: ["base/cmake"], targets: targets)
      yield dir
    end
  end
end

RSpec.describe "relspec compile with per-architecture and per-distribution overlays" do
  include CompiledTarget

  it "applies @<arch>/ overlays to that architecture only, over the common ones" do
    with_release("arch", "bionic: [amd64, arm64]") do |dir|
      overlay = File.join(dir, "overlays", "base", "cmake")
      FileUtils.mkdir_p([File.join(overlay, "debian"), File.join(overlay, "@arm64", "debian")])
      File.write(File.join(overlay, "debian", "NOTE"), "common\n")
      File.write(File.join(overlay, "@arm64", "debian", "NOTE"), "arm64 only\n")
      run = relspec("compile", "specs/arch.yml", "--out", "out", chdir: dir)
      expect(run.exit_code).to eq(0), run.stderr
      notes = %w[amd64 arm64].to_h { |arch| [arch, debian_note(File.join(dir, "out", "arch", "bionic-#{arch}"))] }
      expect(notes).to eq("amd64" => "common\n", "arm64" => "arm64 only\n")
      origs = %w[amd64 arm64].map { |arch| Digest::SHA256.file(Dir.glob(File.join(dir, "out", "arch", "bionic-#{arch}", "*", "*.orig.tar.gz")).first).hexdigest }
      expect(origs.uniq.size).to eq(1)

      FileUtils.mkdir_p(File.join(overlay, "@arm64", "files"))
      run = relspec("compile", "specs/arch.yml", "--out", "out", chdir: dir)
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("error[overlay]: files/ cannot be per architecture")
    end
  end

  it "applies @<codename>/ overlays to that distribution's targets only, and moves only their revisions" do
    with_release("two", "bionic: [amd64], focal: [amd64]") do |dir|
      expect(relspec("compile", "specs/two.yml", "--out", "out", chdir: dir).exit_code).to eq(0)
      targets = %w[bionic focal].to_h { |codename| [codename, File.join(dir, "out", "two", "#{codename}-amd64")] }
      first = targets.transform_values { |target| dsc_names(target) }

      overlay = File.join(dir, "overlays", "base", "cmake", "@focal", "debian")
      FileUtils.mkdir_p(overlay)
      File.write(File.join(overlay, "NOTE"), "focal only\n")
      run = relspec("compile", "specs/two.yml", "--out", "out", chdir: dir)
      expect(run.exit_code).to eq(0), run.stderr
      expect(targets.transform_values { |target| debian_note(target) }).to eq("bionic" => "", "focal" => "focal only\n")
      second = targets.transform_values { |target| dsc_names(target) }
      expect(second["bionic"]).to eq(first["bionic"])
      expect(second["focal"]).not_to eq(first["focal"])

      FileUtils.mkdir_p(File.join(dir, "overlays", "base", "cmake", "@focal", "files"))
      run = relspec("compile", "specs/two.yml", "--out", "out", chdir: dir)
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to include("error[overlay]: files/ cannot be per distribution (use a patch in @focal/patches/)")
    end
  end
end

RSpec.describe "the lock between plan and compile" do
  it "keeps the debian/ digests through plan --write, so a later debian/ change still raises the revision" do
    Dir.mktmpdir("relspec-lock-digests") do |dir|
      fixture = ReleaseFixture.new(dir)
      fixture.standalone("rel", select: ["base/cmake"], targets: "bionic: [amd64]")
      expect(relspec("compile", "specs/rel.yml", "--out", "out", chdir: dir).exit_code).to eq(0)
      lock = File.join(dir, "releases", "rel", "lock.yml")
      digests = File.read(lock).scan(/debian_digest: (\h+)/).flatten
      expect(digests.size).to eq(2) # the decision's and the history's
      expect(digests.uniq.size).to eq(1)
      # from the spec's folder: the lock is still the project's
      expect(relspec("plan", "rel.yml", "--write", chdir: File.join(dir, "specs")).exit_code).to eq(0)
      expect(File.read(lock).scan(/debian_digest: (\h+)/).flatten).to eq(digests)
      expect(File.exist?(File.join(dir, "specs", "releases"))).to be(false)

      FileUtils.mkdir_p(File.join(dir, "overlays", "base", "cmake", "debian"))
      File.write(File.join(dir, "overlays", "base", "cmake", "debian", "NOTE"), "changed\n")
      expect(relspec("compile", "specs/rel.yml", "--out", "out", chdir: dir).exit_code).to eq(0)
      expect(Dir.glob(File.join(dir, "out", "rel", "bionic-amd64", "*", "*.dsc")).first).to end_with("-2~bionic.dsc")
    end
  end

  it "says what it cannot write, as a user error" do
    Dir.mktmpdir("relspec-unwritable") do |dir|
      workspace = DemoWorkspace.build(File.join(dir, "ws")).root
      run = relspec("catalog", "export", workspace, "--targets", "bionic",
                    "--output", File.join(dir, "missing", "folder", "catalog.yml"))
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to match(%r{\Arelspec: error: cannot write #{Regexp.escape(dir)}/missing/folder/catalog.yml: No such file or directory})
    end
  end

  it "goes on from the last revision when a package is built again after being inherited for a while" do
    Dir.mktmpdir("relspec-last-build") do |dir|
      fixture = ReleaseFixture.new(dir)
      fixture.repository("parent", [%w[bionic amd64]], ReleaseFixture::LAYOUT.to_h { |name| [name, {}] })
      fixture.spec("parent", "targets: { bionic: [amd64] }\nrepository: { path: ../repos/parent, trusted: true }\n" \
                             "maintainer: Demo Packaging <demo@example.org>\n")
      blacklisted = "parent: parent\nblacklist: [{ match: base/types, reason: new API }]\n"
      compile = -> { relspec("compile", "specs/child.yml", "--out", "out", chdir: dir) }
      lock = -> { YAML.safe_load(File.read(File.join(dir, "releases", "child", "lock.yml"))) }
      fixture.spec("child", blacklisted, workspace: :checkouts)
      expect(compile.call.exit_code).to eq(0)
      first = lock.call.dig("targets", "bionic/amd64", "base/types")
      expect(first["version"]).to end_with("-1~bionic")

      # the blacklist goes: base/types is inherited, and the lock's history keeps its last build
      fixture.spec("child", "parent: parent\n", workspace: :checkouts)
      expect(relspec("plan", "specs/child.yml", "--write", chdir: dir).exit_code).to eq(0)
      expect(lock.call.dig("targets", "bionic/amd64", "base/types")).to include("decision" => "inherit")
      upstream = first["version"].delete_suffix("-1~bionic")
      expect(lock.call.dig("history", "bionic/amd64", "base/types", upstream))
        .to eq("revision" => 1, "debian_digest" => first["debian_digest"])

      # built again with another debian/: the next revision, never a second, different -1
      fixture.spec("child", blacklisted, workspace: :checkouts)
      FileUtils.mkdir_p(File.join(dir, "overlays", "base", "types", "debian"))
      File.write(File.join(dir, "overlays", "base", "types", "debian", "README.Debian"), "Built for the child.\n")
      expect(compile.call.exit_code).to eq(0)
      expect(lock.call.dig("targets", "bionic/amd64", "base/types", "version")).to end_with("-2~bionic")
    end
  end
end
