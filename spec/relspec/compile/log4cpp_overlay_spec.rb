# frozen_string_literal: true

require "spec_helper"
require_relative "../../support/real_rock_workspace"

# The project's overlays/log4cpp (orocos-toolchain/log4cpp#24: a header
# without <ctime>, which GCC 12 no longer includes through <string>) on the
# real log4cpp of ../shared: compile carries it as a quilt patch that
# dpkg-source applies, and the patched header compiles where upstream's does
# not. The compiler checks the one header (a second) instead of building
# log4cpp (minutes): that is the line the build stopped at.
RSpec.describe "the log4cpp overlay on the real log4cpp" do
  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @workspace = RealRockWorkspace.shared
    @dir = Dir.mktmpdir("relspec-log4cpp")
    FileUtils.mkdir_p(File.join(@dir, "overlays"))
    FileUtils.cp_r(File.join(CliRunner::ROOT, "overlays", "log4cpp"), File.join(@dir, "overlays"))
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "rock.yml"), <<~YAML)
      release: rock
      maintainer: Rock Packaging <rock@example.org>
      workspace: #{@workspace.root}
      select: [log4cpp]
      targets: { bookworm: [amd64] }
      distributions: { bookworm: { archive: { host: true } } }
    YAML
    # what log4cpp's CMake configuration writes into log4cpp/config.h and
    # the header needs (<sstream> instead of its own ostringstream)
    FileUtils.mkdir_p(File.join(@dir, "config", "log4cpp"))
    File.write(File.join(@dir, "config", "log4cpp", "config.h"), "#define LOG4CPP_HAVE_SSTREAM 1\n")
  end

  after(:all) { FileUtils.rm_rf(@dir) if @dir }

  def syntax_check(tree)
    Open3.capture2e("g++", "-fsyntax-only", "-x", "c++", "-I", File.join(tree, "include"),
                    "-I", File.join(@dir, "config"), "-",
                    stdin_data: "#include <log4cpp/DailyRollingFileAppender.hh>\n")
  end

  it "patches the emitted source package so that the header compiles with GCC 12" do
    run = relspec("compile", "specs/rock.yml", "--out", "out", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    dsc = Dir[File.join(@dir, "out", "rock", "bookworm-amd64", "rock-rock-log4cpp", "*.dsc")].first
    tree = File.join(@dir, "tree")
    output, status = Open3.capture2e("dpkg-source", "-x", dsc, tree)
    expect(status).to be_success, output
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
end
