# frozen_string_literal: true

require "spec_helper"
require "open3"
require "yaml"
require_relative "../../support/build_release"
require "relspec/builder/request"
require "relspec/builder/sbuild_backend"
require "relspec/builder/tool"
require "relspec/builder/unpack_dir"

# The sbuild backend for real: a chroot tarball of bookworm made by
# mmdebstrap (unshare mode) from this machine's apt sources, then sbuild
# (unshare mode) builds a package and one that build-depends on it (the
# first one's .deb handed over with --extra-package).
#
# base/one is a macro package as base/cmake is: it installs a CMake module
# that calls pkg-config, which it declares as an OS dependency. base/two uses
# that module at its build time, so the clean chroot has pkg-config only when
# base/two's Build-Depends carry the build-only tools of its dependency
# closure (issue 32; base/one's Depends leave pkg-config out). The module
# also finds Ruby's headers as base/cmake's RockRuby does: autoproj installs
# them for itself in every workspace, so every CMake build gets ruby-dev.
#
# Both compile the same C++ file in folders of other names (sbuild's
# /build/<source>-<random>/<source>-<version>, as a rebuild after a
# blacklist or pin change does): base/two's compile is a hit of the test
# run's ccache (CliRunner::CCACHE), bound into the chroot (root only).
RSpec.describe "relspec build --backend sbuild", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-sbuild")
    # the test run's cache: the chroot tarball is made once for every sbuild test
    @cache = CliRunner::CACHE
    @release = BuildRelease.new(@dir, "sb")
    @release.osdeps("pkg-config:\n  debian: pkg-config\n")
    hello = "enable_language(CXX)\nadd_executable(hello hello.cpp)"
    cpp = { "hello.cpp" => "#include <string>\nint main() { return std::string(\"hello\").size() == 5 ? 0 : 1; }\n" }
    # only in sbuild's chroot (its builds are below /build): the host
    # backend's builds below share this machine's /tmp
    chroot = 'CMAKE_CURRENT_SOURCE_DIR MATCHES "^/build/"'
    mark = ->(name) { "\nif(#{chroot})\n  execute_process(COMMAND touch /tmp/relspec-#{name}-was-here)\nendif()" }
    @release.package("base/one", cmake: "install(FILES one-config.cmake DESTINATION share/cmake/one)\n#{hello}#{mark['one']}",
                                 osdeps: ["pkg-config"], files: { "one-config.cmake" => "find_package(PkgConfig REQUIRED)\nfind_package(Ruby REQUIRED)\n" }.merge(cpp))
    # base/three builds beside base/one (--jobs 2), each on its own layer
    # over the same unpacked chroot; base/two, after base/one, must not see
    # the file base/one's build left in its chroot's /tmp (nor base/three's)
    @release.package("base/three", cmake: "#{hello}#{mark['three']}", files: cpp)
    # base/four declares exactly base/three's Build-Depends: one of them
    # installs them into a build-dependency layer, the other builds on it
    @release.package("base/four", cmake: "#{hello}#{mark['four']}", files: cpp)
    unseen = "\nif(#{chroot} AND (EXISTS /tmp/relspec-one-was-here OR EXISTS /tmp/relspec-three-was-here))\n  " \
             "message(FATAL_ERROR \"another build's file\")\nendif()"
    # the language first: FindRuby finds no library in a project without one
    @release.package("base/two", dependencies: ["base/one"], cmake: "#{hello}\nfind_package(one REQUIRED)#{unseen}", files: cpp)
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  # ccache's counters in the test run's cache folder (ccache of this machine).
  def ccache_stats
    output, status = Open3.capture2("ccache", "--dir", CliRunner::CCACHE, "--print-stats")
    expect(status).to be_success
    output.lines.to_h { |line| line.split("\t").then { |name, value| [name, value.to_i] } }
  end

  def build(*args)
    relspec("build", "specs/sb.yml", "--out", "out", "--backend", "sbuild", *args, chdir: @dir)
  end

  it "makes the chroot (once per cache) and builds in it" do
    # The test run's apt cache is shared by this process's sbuild specs:
    # rock_release_spec, run before this one in some orders, may have kept
    # cmake already, and then no build here downloads it.
    kept_before = Dir.exist?(File.join(CliRunner::APT_CACHE, "bookworm-amd64")) &&
                  Dir.children(File.join(CliRunner::APT_CACHE, "bookworm-amd64")).any? { |name| name.start_with?("cmake_") }
    run = build("--jobs", "2")
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    chroot = File.join(@cache, "relspec", "chroots", "bookworm-amd64.tar.zst")
    expect(File.size(chroot)).to be > 10_000_000
    results = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))
    expect(results.fetch("backend")).to eq("sbuild")
    expect(results.fetch("packages").values.map { |record| record["status"] }).to eq(%w[built built built built])
    two = File.read(File.join(@release.target_dir, "logs", "#{@release.source('base/two')}.log"))
    expect(two).to include("--chroot-mode=unshare")
    # the build-dependency built a moment ago was installed in the chroot
    # (by sbuild from its --extra-package, or into base/two's
    # build-dependency layer), and pkg-config for base/one's CMake module
    # (not in base/one's Depends).
    expect(two).to match(/^\$ .*#{Regexp.escape(@release.source('base/one'))}_\S+\.deb/)
    expect(two).to match(/Unpacking #{Regexp.escape(@release.source('base/one'))} /)
    expect(two).to match(/Unpacking pkg-config:amd64 /)
    expect(two).to include("Found PkgConfig: /usr/bin/pkg-config")
    expect(two).to match(/Unpacking ruby-dev:amd64 /)
    expect(two).to match(/Found Ruby: .*ruby/)
    # fakeroot, which sbuild adds to every build, is in the chroot already
    expect(two).to match(/^Package versions: .* fakeroot_/)
    expect(two).not_to match(/^Unpacking fakeroot /)

    # The chroot is unpacked once (by base/one's or base/three's build,
    # whichever started first), and each build runs on a layer of its own
    # over it: base/two installed pkg-config again (above), so base/one's
    # did not reach it, nor did the files base/one and base/three left.
    one, three, four = %w[base/one base/three base/four].map do |package|
      File.read(File.join(@release.target_dir, "logs", "#{@release.source(package)}.log"))
    end
    if Process.uid.zero?
      unpacking = "$ unshare --user --map-users="
      expect([one, two, three, four].map { |log| log.include?(unpacking) }.count(true)).to eq(1)
      expect(two).not_to include(unpacking)
      expect(two).to match(/^\$ unshare --mount --propagation private -- .* sbuild .*--chroot=\S+empty\.tar /)
      expect(two).not_to include("bookworm-amd64.tar.zst")
      # apt's lists refreshed once in the lower layer (with the unpacking),
      # not in every build; the layer goes as a whole, sbuild removes nothing
      refresh = "chroot \"$1\" apt-get -o Acquire::Languages=none update"
      expect([one, two, three, four].map { |log| log.include?(refresh) }.count(true)).to eq(1)
      expect([one, two, three, four]).to all(satisfy { |log| !log.include?("| Update chroot") && log.include?("Keeping session: ") })

      # Build-dependency layers by exact set: base/three and base/four share
      # one (made by whichever came first, the other waited for it), base/one
      # and base/two have sets of their own; each build's chroot holds
      # exactly its set, so sbuild ran its null resolver and installed
      # nothing, not even its dummy package, and had no .debs to resolve from.
      key = /^relspec: build-dependency layer (\h{16}) \(\d+ packages\) in /
      keys = [one, two, three, four].map { |log| log[key, 1] }
      expect(keys).to all(be_a(String))
      expect(keys[2]).to eq(keys[3])
      expect(keys.uniq.size).to eq(3)
      installing = /^\$ unshare --mount .* apt-get install --yes --no-install-recommends /
      expect([one, two, three, four].map { |log| log.match?(installing) }.count(true)).to eq(3)
      user = [three, four].find { |log| !log.match?(installing) }
      expect(user).not_to match(/^Unpacking cmake /)
      [one, two, three, four].each do |log|
        expect(log).to match(/^\$ unshare --mount .* sbuild .*--build-dep-resolver=null /)
        expect(log).to include("Null resolver: not installing main dependencies")
        expect(log).not_to include("sbuild-build-depends-main-dummy", "--extra-package=")
      end

      # The .debs downloaded (cmake) are kept for the target and base/two's
      # layer, made after base/one's, takes them from there (unless an
      # earlier spec of the run kept it: then nobody downloads it).
      cmake = %r{^Get:\d+ http\S+ bookworm/main amd64 cmake amd64 }
      downloaded = [one, three, four].map { |log| log.match?(cmake) }
      expect(downloaded).to(kept_before ? all(be(false)) : include(true))
      expect(two).to match(/^(Unpacking|Preparing to unpack) .*cmake_/)
      expect(two).not_to match(cmake)
      expect(Dir.children(File.join(CliRunner::APT_CACHE, "bookworm-amd64"))).to include(a_string_matching(/\Acmake_.*\.deb\z/))
    end

    # ccache: on the build's PATH, its folder bound in; base/one's compile
    # missed, base/two's hit. The folder belongs to the chroot's build user
    # (root's first subordinate uid) and nobody else.
    expect(two).to include("PATH=/usr/lib/ccache:", "CCACHE_DIR=/var/cache/ccache")
    stats = ccache_stats
    expect(stats.fetch("cache_miss")).to be >= 1
    expect(stats.fetch("direct_cache_hit") + stats.fetch("preprocessed_cache_hit")).to be >= 1
    folder = File.stat(CliRunner::CCACHE)
    expect([folder.uid, folder.mode & 0o777]).to eq([File.read("/etc/subuid")[/^root:(\d+):/, 1].to_i, 0o700])

    mtime = File.mtime(chroot)
    again = build("--prepare")
    expect(again.exit_code).to eq(0), again.stderr
    expect(again.stdout).to eq("bookworm/amd64: chroot ready\n")
    expect(File.mtime(chroot)).to eq(mtime)

    # Another backend's builds are not reused: host builds both again.
    host = relspec("build", "specs/sb.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(host.stdout).to include("bookworm/amd64: 4 built, 0 already built")
  end

  # The null resolver installs nothing, so a chroot without a build's
  # Build-Depends must still fail it: dpkg-buildpackage checks them in the
  # chroot (dpkg-checkbuilddeps; sbuild passes no -d). DependencyLayers is
  # stubbed to claim base/three's set installed while the chroot has no
  # cmake: a wrong answer that relspec's own resolution cannot give.
  # The kept build-dependency layers are bounded (docs/build.md, "A bound
  # on the kept layers"): with a budget no layer fits in, every build
  # goes without one, resolved and installed by sbuild's apt as with
  # RELSPEC_DEPENDENCY_LAYERS=off, and still builds.
  it "builds everything without build-dependency layers when the budget leaves no room for one" do
    skip "the chroot's layers need root" unless Process.uid.zero?

    run = relspec("build", "specs/sb.yml", "--out", "out", "--backend", "sbuild", "--rebuild", "--jobs", "2",
                  chdir: @dir, env: { "RELSPEC_LAYER_BUDGET" => "1" })
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    results = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))
    expect(results.fetch("packages").values.map { |record| record["status"] }).to eq(%w[built built built built])
    logs = %w[base/one base/two base/three base/four].map do |package|
      File.read(File.join(@release.target_dir, "logs", "#{@release.source(package)}.log"))
    end
    logs.each do |log|
      expect(log).to match(/^relspec: no build-dependency layer \h{16}: no room \(the layers in use take 0\.0 GB, .* of a budget of 0\.0 GB/)
      expect(log).not_to match(/^relspec: build-dependency layer \h{16} .* in /)
      expect(log).not_to include("--build-dep-resolver=null")
      expect(log).to match(/^Unpacking cmake /)
    end
  end

  it "fails a build whose Build-Depends are missing under sbuild's null resolver (dpkg-buildpackage checks them)" do
    skip "the chroot's layers need root" unless Process.uid.zero?

    dsc = Dir.glob(File.join(@dir, "**", "#{@release.source('base/three')}_*.dsc")).first
    claimed = Relspec::Builder::DependencyLayers::Installed.new(folder: nil, complete: true)
    allow_any_instance_of(Relspec::Builder::DependencyLayers).to receive(:for).and_return(claimed)
    unpack_dir = Relspec::Builder::UnpackDir.new
    backend = Relspec::Builder::SbuildBackend.new(Relspec::Builder::Tool.new, {}, chroot_cache: File.join(@cache, "relspec", "chroots"),
                                                                                  unpack_dir: unpack_dir, ccache: nil, apt_cache: nil)
    log = File.join(@dir, "null-resolver.log")
    request = Relspec::Builder::Request.new(source: @release.source("base/three"), version: "1", dsc: dsc,
                                            target: Relspec::Target.new("bookworm", "amd64"), repositories: [],
                                            local_debs: [], output_dir: File.join(@dir, "null-out"), log: log)
    expect { backend.build(request) }.to raise_error(Relspec::BuildError, /sbuild failed/)
    backend.finish
    text = File.read(log)
    expect(text).to include("--build-dep-resolver=null", "Null resolver: not installing main dependencies")
    expect(text).to match(/^dpkg-checkbuilddeps: error: Unmet build dependencies: .*\bcmake\b/)
    expect(Dir.exist?(File.join(@dir, "null-out"))).to be(false)
  end

  it "says which setting provides a mirror when a chroot cannot be made" do
    File.write(@release.spec_path, File.read(@release.spec_path).sub("bookworm: [amd64]", "bookworm: [amd64], bullseye: [amd64]"))
    compile = relspec("compile", "specs/sb.yml", "--out", "out", "--no-check", chdir: @dir)
    expect(compile.exit_code).to eq(0), compile.stderr
    run = build("--target", "bullseye/amd64", "--prepare")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: cannot make the chroot for bullseye/amd64: no mirror of bullseye " \
                             "(set distributions.bullseye.archive.url in the spec; this machine's apt sources are " \
                             "used only when the codename is the host's own, here bookworm)\n")
  end
end
