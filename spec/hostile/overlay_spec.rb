# frozen_string_literal: true

require "spec_helper"

# Hostile overlays (issue 12, cases 6 and 7; issue 34, case 14), through the
# real CLI: a linked overlay folder, patch names quilt's series file cannot
# carry and file names that are not UTF-8 are refused with the path in the
# message, and nothing is emitted.
RSpec.describe "relspec compile on hostile overlays" do
  # One fixture for all (building it is most of the time); each example
  # starts without overlays and without output.
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-overlay")
    @spec = ReleaseFixture.new(@dir).standalone("h", select: ["base/cmake"], targets: "bionic: [amd64]")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after { FileUtils.rm_rf([File.join(@dir, "overlays"), File.join(@dir, "out"), File.join(@dir, "outside")]) }

  def compile
    relspec("compile", @spec, "--out", "out", "--no-check", chdir: @dir)
  end

  def expect_refused(run, message)
    expect(run.exit_code).to eq(1), run.stderr
    expect(run.stderr).to include(message)
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(Dir.glob(File.join(@dir, "out", "h", "*", "*"))).to eq([])
  end

  it "refuses overlays/<package> that is itself a link to a folder outside the project" do
    outside = File.join(@dir, "outside")
    FileUtils.mkdir_p(File.join(outside, "files"))
    File.write(File.join(outside, "files", "stolen"), "not part of the project\n")
    FileUtils.mkdir_p(File.join(@dir, "overlays", "base"))
    File.symlink(outside, File.join(@dir, "overlays", "base", "cmake"))
    expect_refused(compile, "overlays/base/cmake: error[overlay]: overlays/base/cmake is a link (to #{outside}); " \
                            "an overlay must be a folder of the project")
  end

  ["my patch.patch", "evil\n01.patch", "#hidden.patch"].each do |name|
    it "refuses the patch name #{name.inspect}" do
      patches = File.join(@dir, "overlays", "base", "cmake", "patches")
      FileUtils.mkdir_p(patches)
      File.write(File.join(patches, name), "--- a/x\n+++ b/x\n")
      expect_refused(compile, "error[overlay]: patch name #{name.inspect} cannot be listed in debian/patches/series")
    end
  end

  %w[files patches debian].each do |part|
    it "refuses a file name that is not UTF-8 in #{part}/" do
      folder = File.join(@dir, "overlays", "base", "cmake", part)
      FileUtils.mkdir_p(folder)
      File.binwrite(File.join(folder.b, "caf\xE9.patch".b), "--- a/x\n+++ b/x\n")
      expect_refused(compile, "overlays/base/cmake/#{part}/caf\\xE9.patch: error[overlay]: the file name is not UTF-8")
    end
  end
end
