# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

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
RSpec.describe "relspec build --backend sbuild", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-sbuild")
    # the test run's cache: the chroot tarball is made once for every sbuild test
    @cache = CliRunner::CACHE
    @release = BuildRelease.new(@dir, "sb")
    @release.osdeps("pkg-config:\n  debian: pkg-config\n")
    @release.package("base/one", cmake: "install(FILES one-config.cmake DESTINATION share/cmake/one)",
                                 osdeps: ["pkg-config"], files: { "one-config.cmake" => "find_package(PkgConfig REQUIRED)\nenable_language(C)\nfind_package(Ruby REQUIRED)\n" })
    @release.package("base/two", dependencies: ["base/one"], cmake: "find_package(one REQUIRED)")
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def build(*args)
    relspec("build", "specs/sb.yml", "--out", "out", "--backend", "sbuild", *args, chdir: @dir)
  end

  it "makes the chroot (once per cache) and builds in it" do
    run = build("--jobs", "2")
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    chroot = File.join(@cache, "relspec", "chroots", "bookworm-amd64.tar.zst")
    expect(File.size(chroot)).to be > 10_000_000
    results = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))
    expect(results.fetch("backend")).to eq("sbuild")
    expect(results.fetch("packages").values.map { |record| record["status"] }).to eq(%w[built built])
    two = File.read(File.join(@release.target_dir, "logs", "#{@release.source('base/two')}.log"))
    expect(two).to include("--chroot-mode=unshare", "--extra-package=", "#{@release.source('base/one')}_")
    # sbuild installed the build-dependency built a moment ago in the chroot,
    # and pkg-config for base/one's CMake module (not in base/one's Depends).
    expect(two).to match(/Unpacking #{Regexp.escape(@release.source('base/one'))} /)
    expect(two).to match(/Unpacking pkg-config:amd64 /)
    expect(two).to include("Found PkgConfig: /usr/bin/pkg-config")
    expect(two).to match(/Unpacking ruby-dev:amd64 /)
    expect(two).to match(/Found Ruby: .*ruby/)

    mtime = File.mtime(chroot)
    again = build("--prepare")
    expect(again.exit_code).to eq(0), again.stderr
    expect(again.stdout).to eq("bookworm/amd64: chroot ready\n")
    expect(File.mtime(chroot)).to eq(mtime)

    # Another backend's builds are not reused: host builds both again.
    host = relspec("build", "specs/sb.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(host.stdout).to include("bookworm/amd64: 2 built, 0 already built")
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
