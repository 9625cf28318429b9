# frozen_string_literal: true

require "spec_helper"

# A package that Build-Depends on another one built in the same release finds
# it: the first .deb is installed on this machine (the test runs as root, as
# CI does, and removes it afterwards), then the second builds with its
# build dependencies checked.
RSpec.describe "building a compiled package against its dependency" do
  around do |example|
    Dir.mktmpdir("relspec-build-against") do |dir|
      @dir = dir
      @fixture = ReleaseFixture.new(dir)
      @fixture.standalone("solo", select: ["base/logging"], targets: "bionic: [amd64]")
      example.run
    ensure
      system("dpkg", "--purge", "rock-solo-base-cmake", out: File::NULL, err: File::NULL)
    end
  end

  def build(package, work, *options)
    dsc = Dir.glob(File.join(@dir, "out", "solo", "bionic-amd64", @fixture.deb("solo", package), "*.dsc")).first
    unless File.directory?(File.join(work, package.tr("/", "-")))
      output, status = Open3.capture2e("dpkg-source", "-x", dsc, package.tr("/", "-"), chdir: work)
      raise output unless status.success?
    end

    Open3.capture2e("dpkg-buildpackage", "-us", "-uc", "-b", *options, chdir: File.join(work, package.tr("/", "-")))
  end

  it "installs the first package and builds the second with its build dependencies satisfied" do
    expect(Process.uid).to eq(0), "this test installs a .deb: run it as root (CI does)"
    run = relspec("compile", "specs/solo.yml", "--out", "out", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    Dir.mktmpdir("relspec-build") do |work|
      output, status = build("base/cmake", work)
      expect(status).to be_success, output.lines.last(15).join
      output, status = build("base/logging", work)
      expect(status).not_to be_success # rock-solo-base-cmake is not installed yet
      expect(output).to include("Unmet build dependencies: rock-solo-base-cmake")

      deb = Dir.glob(File.join(work, "rock-solo-base-cmake_*_amd64.deb")).first
      output, status = Open3.capture2e("dpkg", "-i", deb)
      expect(status).to be_success, output
      output, status = build("base/logging", work)
      expect(status).to be_success, output.lines.last(15).join
      expect(output).to include("found base/cmake in /opt/rock/solo/rock-solo-base-cmake/share")
    end
  end
end
