# frozen_string_literal: true

require "spec_helper"

# Broken workspaces, through the real CLI: one clear message, exit 1, no
# backtrace, nothing written.
RSpec.describe "relspec catalog on broken workspaces" do
  around do |example|
    Dir.mktmpdir("relspec-broken") do |base|
      @base = base
      example.run
    end
  end

  def broken_workspace
    builder = DemoWorkspace.build(@base)
    yield builder
    builder.root
  end

  def expect_failure(run, message)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).to include(message)
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
  end

  def show(root, spec_body = "")
    specs = File.join(@base, "specs")
    FileUtils.mkdir_p(specs)
    File.write(File.join(specs, "rel.yml"), "release: rel\nworkspace: #{root}\ntargets: { bionic: [amd64] }\n#{spec_body}")
    relspec("catalog", "show", File.join(specs, "rel.yml"))
  end

  it "says when a folder is not a workspace" do
    expect_failure(relspec("catalog", "export", @base),
                   "#{@base}: error[not-a-workspace]: #{@base} is not an autoproj workspace (no .autoproj/config.yml)")
  end

  it "names .autoproj/config.yml and the place when it is malformed YAML" do
    root = broken_workspace { |b| File.write(File.join(b.root, ".autoproj", "config.yml"), "source: src\n  bad: [\n") }
    expect_failure(relspec("catalog", "export", root, "--targets", "bionic"),
                   "#{root}/.autoproj/config.yml:2:6: error[workspace-config]: malformed .autoproj/config.yml: " \
                   "mapping values are not allowed in this context")
  end

  it "says when a package set is missing" do
    root = broken_workspace { |b| FileUtils.rm_rf(File.join(b.root, "package_sets")) }
    expect_failure(relspec("catalog", "export", root, "--targets", "bionic"),
                   "autoproj/manifest: error[missing-package-set]: package set ../package_sets/demo.pkgs does not exist")
  end

  it "says when a package of the release is not checked out" do
    root = broken_workspace { |b| FileUtils.rm_rf(b.source_dir("base/logging")) }
    expect_failure(show(root), "error[not-checked-out]: base/logging is part of the release but not checked out at " \
                               "src/base/logging")
  end

  it "points at the line of a broken manifest.xml" do
    root = broken_workspace do |b|
      File.write(File.join(b.source_dir("base/types"), "manifest.xml"), "<package>\n  <depend package=\"x\">\n</package>\n")
    end
    expect_failure(relspec("catalog", "export", root, "--targets", "bionic"),
                   "src/base/types/manifest.xml:3:1: error[package-manifest]: broken manifest.xml")
  end

  it "names the layout's metapackage, the package, the osdep and the target of an osdep defined for other systems only" do
    root = broken_workspace do |b|
      osdeps = File.join(b.root, "package_sets", "demo.pkgs", "demo.pkgs.osdeps")
      File.write(osdeps, "#{File.read(osdeps)}macos-only:\n  macos-brew: foo\n")
      manifest = File.join(b.source_dir("base/logging"), "manifest.xml")
      File.write(manifest, File.read(manifest).sub("</package>", "  <depend package=\"macos-only\"/>\n</package>"))
    end
    # autoproj excludes base/logging there, and refuses the layout's strong metapackage that needs it
    expect_failure(show(root), "error[unavailable-selection]: demo.core is in the layout, but its package base/logging " \
                               "cannot be built on bionic: it needs the osdep macos-only, which the osdeps files define " \
                               "for other systems only")
  end
end
