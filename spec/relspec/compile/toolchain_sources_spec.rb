# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/real_rock_workspace"

# Source packages of the real Rock toolchain (../shared) that once failed to
# build, each checked at the step it failed at instead of a build of minutes
# (bin/toolchain builds them for real, docs/performance.md):
# - log4cpp: the project's overlays/log4cpp (orocos-toolchain/log4cpp#24, a
#   header without <ctime>, which GCC 12 no longer includes through
#   <string>) is carried as a quilt patch and the patched header compiles;
# - utilmm: its own upstream debian/ (compat 9, .install files) stays out
#   of the generated packaging, so dh accepts it;
# - tools/class_loader: rock.core's import patch (patches/
#   class_loader_pkgconfig.patch, level 0) was dropped; it is now the first
#   quilt patch of the source package, rewritten for -p1.
RSpec.describe "source packages of the real Rock toolchain" do
  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @workspace = RealRockWorkspace.shared
    @dir = Dir.mktmpdir("relspec-toolchain")
    FileUtils.mkdir_p(File.join(@dir, "overlays"))
    FileUtils.cp_r(File.join(CliRunner::ROOT, "overlays", "log4cpp"), File.join(@dir, "overlays"))
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rock.yml"), <<~YAML)
      release: rock
      maintainer: Rock Packaging <rock@example.org>
      workspace: #{@workspace.root}
      select: [log4cpp, utilmm, tools/class_loader]
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
    YAML
    # what log4cpp's CMake configuration writes into log4cpp/config.h and
    # the header needs (<sstream> instead of its own ostringstream)
    FileUtils.mkdir_p(File.join(@dir, "config", "log4cpp"))
    File.write(File.join(@dir, "config", "log4cpp", "config.h"), "#define LOG4CPP_HAVE_SSTREAM 1\n")
    @compile = relspec("compile", "specs/rock.yml", "--out", "out", chdir: @dir)
  end

  after(:all) { FileUtils.rm_rf(@dir) if @dir }

  # [dpkg-source -x output, unpacked tree] of one emitted source package
  def unpack(source)
    dsc = Dir[File.join(@dir, "out", "rock", "bookworm-amd64", source, "*.dsc")].first
    tree = File.join(@dir, "tree-#{source}")
    output, status = Open3.capture2e("dpkg-source", "-x", dsc, tree)
    expect(status).to be_success, output
    [output, tree]
  end

  def syntax_check(tree)
    Open3.capture2e("g++", "-fsyntax-only", "-x", "c++", "-I", File.join(tree, "include"),
                    "-I", File.join(@dir, "config"), "-",
                    stdin_data: "#include <log4cpp/DailyRollingFileAppender.hh>\n")
  end

  it "patches log4cpp so that its header compiles with GCC 12" do
    expect(@compile.exit_code).to eq(0), @compile.stderr
    output, tree = unpack("rock-rock-log4cpp")
    expect(output).to include("applying ctime-for-struct-tm.patch")
    expect(File.read(File.join(tree, "debian", "patches", "series"))).to eq("ctime-for-struct-tm.patch\n")
    expect(File.read(File.join(tree, "include", "log4cpp", "DailyRollingFileAppender.hh")))
      .to include("#include <stdarg.h>\n#include <ctime>\n")
    output, status = syntax_check(tree)
    expect(status).to be_success, output

    # upstream as checked out still fails: the day it compiles, the overlay can go
    output, status = syntax_check(@workspace.source_dir("log4cpp"))
    expect(status).not_to be_success
    expect(output).to include("field '_logsTime' has incomplete type 'tm'").or include("field ‘_logsTime’ has incomplete type ‘tm’")
  end

  it "packages utilmm with relspec's debian/ only, which dh accepts" do
    expect(@compile.exit_code).to eq(0), @compile.stderr
    expect(File).to exist(File.join(@workspace.source_dir("utilmm"), "debian", "compat"))
    _, tree = unpack("rock-rock-utilmm")
    expect(Dir.children(File.join(tree, "debian")).sort)
      .to eq(%w[changelog control copyright env.sh env.yml relspec.yml rock-rock-utilmm.lintian-overrides rules source])
    # the step that failed: dh read both debian/compat and debhelper-compat
    output, status = Open3.capture2e("debian/rules", "clean", chdir: tree)
    expect(status).to be_success, output
  end

  it "carries rock.core's import patch of tools/class_loader as a quilt patch dpkg-source applies" do
    expect(@compile.exit_code).to eq(0), @compile.stderr
    name = "autoproj-01-class_loader_pkgconfig.patch"
    output, tree = unpack("rock-rock-tools-class-loader")
    expect(output).to include("applying #{name}")
    expect(File.read(File.join(tree, "debian", "patches", "series"))).to eq("#{name}\n")
    patch = File.read(File.join(tree, "debian", "patches", name))
    expect(patch).to start_with("Description: .autoproj/remotes/github__rock_core_package_set_git/patches/" \
                                "class_loader_pkgconfig.patch (package set patch of tools/class_loader")
    expect(patch).to include("--- a/src/class_loader.pc.in\n+++ b/src/class_loader.pc.in\n")
    expect(File.read(File.join(tree, "src", "class_loader.pc.in"))).to include("Requires: console_bridge @PKGCONFIG_REQUIRES@")
    # the .orig is the upstream tree: the patch is not in it
    orig = Dir[File.join(@dir, "out", "rock", "bookworm-amd64", "rock-rock-tools-class-loader", "*.orig.tar.gz")].first
    listing, = Open3.capture2("tar", "-xzOf", orig, "--wildcards", "*/src/class_loader.pc.in")
    expect(listing).to include("Requires: @PKGCONFIG_REQUIRES@")
  end
end
