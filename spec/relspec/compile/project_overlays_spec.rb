# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require_relative "../../support/real_rock_workspace"

# The project's own overlays (overlays/<package>/patches, each an upstream
# bug, docs/compile.md) against the real sources they patch (../shared):
# every patch still applies, and the ones whose effect can be checked in
# seconds do what they say. The toolchain acceptance (spec/toolchain) builds
# and uses all of them.
RSpec.describe "the project's overlays on the real Rock sources" do
  PATCHES = Dir[File.join(CliRunner::ROOT, "overlays", "**", "patches", "*.patch")].sort
  # the toolchain tests' own (base/types without SISL, docs/compile.md)
  TEST_PATCHES = Dir[File.join(CliRunner::ROOT, "spec", "fixtures", "toolchain_overlays", "**", "patches", "*.patch")].sort

  before(:all) do
    need_fixture(RealRockWorkspace.available?, RealRockWorkspace.skip_reason)
    @workspace = RealRockWorkspace.shared
  end

  # the package a patch is for, without its @<codename>/@<arch> layer
  def package_of(patch)
    File.dirname(patch, 2).split(%r{/(?:toolchain_)?overlays/}).last.sub(%r{/@[^/]+\z}, "")
  end

  # The toolchain's packages are in the shared workspace; the core release's
  # others (gui/osgviz) are cloned alone from their bundle, named after the
  # package (slashes as dashes).
  def source_dir(package)
    known = RealRockWorkspace::PACKAGES[package]
    return File.join(@workspace.root, "src", known.last) if known

    dir = File.join(@workspace.root, "overlay-sources", package)
    unless File.directory?(dir)
      bundle = RealRockWorkspace.bundle_path(package.tr("/", "-"))
      output, status = Open3.capture2e("git", "clone", "-q", bundle, dir)
      raise "cannot clone #{bundle}: #{output}" unless status.success?
    end
    dir
  end

  it "has a patch for each upstream bug docs/compile.md lists" do
    listed = File.read(File.join(CliRunner::ROOT, "docs", "compile.md")).scan(%r{`(overlays/[^`]+\.patch)`}).flatten
    expect(PATCHES.map { |patch| patch.delete_prefix("#{CliRunner::ROOT}/") }).to match_array(listed)
  end

  it "says for each listed patch the targets its layer gives it (@<codename>/: that distribution only)" do
    rows = File.read(File.join(CliRunner::ROOT, "docs", "compile.md")).scan(%r{^\| `(overlays/[^`]+\.patch)` \| ([^|]+) \|})
    expect(rows).not_to be_empty
    rows.each do |path, targets|
      layer = path[%r{/@([^/]+)/patches/}, 1]
      expect(targets.strip).to eq(layer ? "#{layer} only" : "every target"), path
    end
  end

  (PATCHES + TEST_PATCHES).each do |patch|
    it "applies #{File.basename(patch)} to the real #{File.dirname(patch, 2).split('/overlays/').last}" do
      output, status = Open3.capture2e("git", "apply", "--check", "-p1", patch, chdir: source_dir(package_of(patch)))
      expect(status).to be_success, output
      expect(File.read(patch)).to match(/\ADescription: .+\n(?: .*\n)+/)
    end
  end

  it "makes utilrb's PkgConfig find the system's .pc folders with pkgconf (Debian 12's pkg-config)" do
    Dir.mktmpdir("relspec-utilrb") do |dir|
      FileUtils.cp_r(File.join(source_dir("utilrb"), "lib"), dir)
      check = 'require "utilrb/pkgconfig"; puts Utilrb::PkgConfig.default_search_path.join(":")'
      pc_path = Open3.capture2("pkg-config", "--variable", "pc_path", "pkg-config").first.strip
      before, = Open3.capture2e(RbConfig.ruby, "-I", File.join(dir, "lib"), "-e", check)
      # the bug itself, on this machine's pkgconf: nothing found
      expect(before.lines.last.to_s.strip).to eq("")
      patch = Dir[File.join(CliRunner::ROOT, "overlays", "utilrb", "patches", "*.patch")].first
      output, status = Open3.capture2e("patch", "-p1", "-i", patch, chdir: dir)
      expect(status).to be_success, output
      after, status = Open3.capture2e(RbConfig.ruby, "-I", File.join(dir, "lib"), "-e", check)
      expect(status).to be_success, after
      expect(after.lines.last.strip).to eq(pc_path)
    end
  end
end
