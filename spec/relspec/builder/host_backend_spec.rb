# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

# The host backend installs nothing: a build-dependency missing on this
# machine fails the build, named, before dpkg-buildpackage runs.
RSpec.describe "relspec build --backend host" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-host")
    @release = BuildRelease.new(@dir, "hb")
    @release.osdeps("absent:\n  debian: relspec-test-absent-package\n")
    @release.package("base/needs", osdeps: ["absent"])
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  it "names a build-dependency missing on this machine" do
    run = relspec("build", "specs/hb.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(1)
    source = @release.source("base/needs")
    record = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"][source]
    expect(record["status"]).to eq("failed")
    expect(record["reason"]).to eq("#{source}: build-dependencies missing on this machine: relspec-test-absent-package " \
                                   "(relspec looked at the packages installed here, as dpkg-checkbuilddeps does; " \
                                   "install them, or build with --backend sbuild), see logs/#{source}.log")
    expect(run.stdout).to include("bookworm/amd64: 0 built, 0 already built, 1 failed, 0 skipped")
    expect(File.read(File.join(@release.target_dir, "logs", "#{source}.log"))).not_to include("dpkg-buildpackage")
    # stdout is a pipe here, as in CI logs: a line per package start and end before the table
    lines = run.stdout.lines
    expect(lines.first(2)).to eq(["bookworm/amd64: 1 package, 0 already built\n",
                                  "bookworm/amd64 [0/1] started #{source}\n"])
    expect(lines[2]).to match(%r{\Abookworm/amd64 \[1/1\] failed #{source} in \d+\.\d s\n\z})
    expect(lines[3]).to start_with("bookworm/amd64: 0 built, 0 already built, 1 failed, 0 skipped")
    expect(run.stderr).to eq("") # no bar: stderr is no terminal
  end

  it "refuses a release that was not compiled, saying what to run" do
    run = relspec("build", "specs/hb.yml", "--out", "elsewhere", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(1)
    # named as the user gave --out (relative to where relspec runs)
    expect(run.stderr).to eq("relspec: error: elsewhere/hb/bookworm-amd64/plan.yml does not exist: run `relspec compile` first\n")
  end

  it "refuses a target the release does not have" do
    run = relspec("build", "specs/hb.yml", "--out", "out", "--backend", "host", "--target", "trixie/amd64", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: trixie/amd64 is not a target of hb (bookworm/amd64)\n")
  end
end

# dpkg-checkbuilddeps lists the relations it misses separated by spaces:
# every one that the run built must be laid over /opt, and only the others
# are missing on this machine.
RSpec.describe "relspec build --backend host with several build-dependencies of the release" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-host-several")
    @release = BuildRelease.new(@dir, "hs")
    @release.osdeps("absent:\n  debian: relspec-test-absent-package\n")
    @release.package("base/a")
    @release.package("base/b")
    @release.package("base/both", dependencies: %w[base/a base/b])
    @release.package("base/lacks", dependencies: %w[base/a base/b], osdeps: ["absent"])
    @release.package("base/breaks", dependencies: %w[base/a], cmake: 'message(FATAL_ERROR "broken on purpose")')
    @release.compile
    @run = relspec("build", "specs/hs.yml", "--out", "out", "--backend", "host", "--keep-going", chdir: @dir)
    @records = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"]
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def log(package)
    File.read(File.join(@release.target_dir, "logs", "#{@release.source(package)}.log"))
  end

  it "lays every build-dependency built in the run over /opt" do
    # every package has a record, whatever its fate; else the run itself ended early
    expect(@records.keys.sort).to eq(%w[base/a base/b base/both base/breaks base/lacks].map { |name| @release.source(name) }.sort),
                                  "#{@run.stdout}#{@run.stderr}"
    expect(@records.fetch(@release.source("base/both"))["status"]).to eq("built"), log("base/both")
    %w[base/a base/b].each do |dependency|
      expect(log("base/both")).to match(%r{\$ dpkg-deb -x \S+/#{@release.source(dependency)}_\S+[.]deb })
    end
  end

  it "names only the build-dependency this machine lacks" do
    record = @records.fetch(@release.source("base/lacks"))
    expect(record["status"]).to eq("failed")
    expect(record["reason"]).to start_with("#{@release.source('base/lacks')}: build-dependencies missing on this " \
                                           "machine: relspec-test-absent-package (relspec looked")
  end

  it "names the build tool that failed, not the wrapper laying the build-dependencies over /opt" do
    record = @records.fetch(@release.source("base/breaks"))
    expect(record["reason"]).to start_with("#{@release.source('base/breaks')}: dpkg-buildpackage failed (exit status ")
    expect(log("base/breaks")).to include("$ unshare --mount", "broken on purpose")
  end
end

# What apt would install with a build-dependency of the release, the host
# backend lays over /opt too: base/top names only base/mid, which depends on
# base/lib, whose shared library base/top links. dpkg does not know these
# packages as installed, so their shlibs must reach dpkg-shlibdeps through
# debian/shlibs.local (rtt_typelib linking typelib failed there).
RSpec.describe "relspec build --backend host with a library two steps away" do
  LIBRARY = <<~CMAKE
    enable_language(C)
    file(WRITE ${CMAKE_BINARY_DIR}/lib.c "int relspec_answer(void) { return 42; }\\n")
    add_library(answer SHARED ${CMAKE_BINARY_DIR}/lib.c)
    set_target_properties(answer PROPERTIES SOVERSION 1)
    install(TARGETS answer LIBRARY DESTINATION lib)
  CMAKE
  PROGRAM = <<~CMAKE
    enable_language(C)
    file(WRITE ${CMAKE_BINARY_DIR}/main.c "int relspec_answer(void);\\nint main(void) { return relspec_answer() == 42 ? 0 : 1; }\\n")
    add_executable(asker ${CMAKE_BINARY_DIR}/main.c)
    target_link_libraries(asker /opt/rock/ht/rock-ht-base-lib/lib/libanswer.so)
    set_target_properties(asker PROPERTIES INSTALL_RPATH /opt/rock/ht/rock-ht-base-lib/lib)
    install(TARGETS asker RUNTIME DESTINATION bin)
  CMAKE

  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-host-transitive")
    @release = BuildRelease.new(@dir, "ht")
    @release.package("base/lib", cmake: LIBRARY)
    @release.package("base/mid", dependencies: %w[base/lib])
    @release.package("base/top", dependencies: %w[base/mid], cmake: PROGRAM)
    @release.compile
    @run = relspec("build", "specs/ht.yml", "--out", "out", "--backend", "host", chdir: @dir)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  it "links a library of a package its build-dependency depends on, and depends on that package" do
    top = @release.source("base/top")
    log = File.read(File.join(@release.target_dir, "logs", "#{top}.log"))
    expect(@run.exit_code).to eq(0), "#{@run.stderr}\n#{log.lines.last(30).join}"
    control = Open3.capture2("dpkg-deb", "-f", *Dir[File.join(@release.target_dir, "results", top, "#{top}_*.deb")],
                             "Depends").first
    # the library's package comes from its shlibs, as it would with apt
    expect(control).to match(/\brock-ht-base-lib \(>= [^)]+\)/)
    expect(log).to include("# shlibs of the packages laid over /opt:\nlibanswer 1 rock-ht-base-lib")
  end
end
