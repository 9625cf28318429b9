# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/import_patch"
require "relspec/debian/package_set_patch"

# A package set's import patch rewritten for quilt's -p1, in memory.
RSpec.describe Relspec::Debian::PackageSetPatch do
  def patch(content, level: 0, path: "set/patches/fix.patch")
    Relspec::Catalog::ImportPatch.new(path: path, level: level, content: content).freeze
  end

  def rewrite(content, level: 0, files: [])
    described_class.of(patch(content, level: level), index: 0, package_name: "tools/x",
                                                     exists: ->(path) { files.include?(path) })
  end

  it "picks the name that exists, as patch -p0 does with rock.core's class_loader patch, and keeps the hunks" do
    name, text = rewrite(<<~PATCH, files: ["src/x.pc.in"])
      diff -urN ../class_loader/src/x.pc.in ./src/x.pc.in
      --- ../class_loader/src/x.pc.in\t2020-09-29 14:49:35.494450037 +0200
      +++ ./src/x.pc.in\t2020-09-29 14:48:23.101899458 +0200
      @@ -1,2 +1,2 @@
       Name: x
      -Requires: @R@
      +Requires: console_bridge @R@
    PATCH
    expect(name).to eq("autoproj-01-fix.patch")
    expect(text).to eq(<<~TEXT)
      Description: set/patches/fix.patch (package set patch of tools/x, applied by autoproj with patch -p0)
      Forwarded: not-needed
      ---
      diff -urN ../class_loader/src/x.pc.in ./src/x.pc.in
      --- a/src/x.pc.in
      +++ b/src/x.pc.in
      @@ -1,2 +1,2 @@
       Name: x
      -Requires: @R@
      +Requires: console_bridge @R@
    TEXT
  end

  it "strips as many components as the level says, keeps /dev/null, and leaves hunk lines alone" do
    _, text = rewrite(<<~PATCH, level: 2, files: ["lib/a.c"])
      --- /dev/null
      +++ x/y/CMakeLists.txt
      @@ -0,0 +1,2 @@
      +--- not a header
      ++++ either
      --- x/y/lib/a.c
      +++ x/y/lib/a.c
      @@ -1 +1 @@
      --- removed line that looks like a header
      ++++ added line that looks like one
    PATCH
    expect(text.lines.drop(3).join).to eq(<<~TEXT)
      --- /dev/null
      +++ b/CMakeLists.txt
      @@ -0,0 +1,2 @@
      +--- not a header
      ++++ either
      --- a/lib/a.c
      +++ b/lib/a.c
      @@ -1 +1 @@
      --- removed line that looks like a header
      ++++ added line that looks like one
    TEXT
  end

  it "gives every patch a name debian/patches/series can carry, in autoproj's order" do
    name, = described_class.of(patch("", path: "set/patches/my fix.diff"), index: 11, package_name: "x",
                                                                           exists: ->(_) { false })
    expect(name).to eq("autoproj-12-my_fix.diff.patch")
  end

  it "refuses a patch that names no file inside the package's folder" do
    expect { rewrite("--- ../../etc/passwd\n+++ ../../etc/passwd\n@@ -1 +1 @@\n-a\n+b\n") }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to include("names no file inside") }
    expect { rewrite("--- a/x\n+++ b/x\n@@ -1 +1 @@\n-a\n+b\n", level: 2) }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to include("fewer than 3 path components") }
  end

  # Issue 46, case 16: dpkg-source stopped later at "can't find file to patch".
  it "refuses a patch whose file the package does not have at the patch's level, naming patch, file and level" do
    text = "--- a/src/main.c\n+++ b/src/main.c\n@@ -1 +1 @@\n-a\n+b\n"
    expect { rewrite(text, files: ["src/main.c"]) }.to raise_error(Relspec::InvalidInput) do |error|
      expect(error.diagnostics.map(&:to_s)).to eq(
        ["set/patches/fix.patch: error[package-set-patch]: package set patch set/patches/fix.patch changes a/src/main.c or " \
         "b/src/main.c, which the package's source does not have at level 0 (patch -p0)\n  hint: fix the patch's file " \
         "names, or its level in the package set (`patches: [[file, level]]`; autobuild's default level is 0, a patch " \
         "made by `diff -ru a/ b/` needs 1)"]
      )
    end
    expect(rewrite(text, level: 1, files: ["src/main.c"]).last).to include("--- a/src/main.c\n+++ b/src/main.c\n")
    expect { rewrite("--- gone.c\n+++ /dev/null\n@@ -1 +0,0 @@\n-a\n") }
      .to raise_error(Relspec::InvalidInput) { |e| expect(e.diagnostics.first.message).to eq("package set patch set/patches/fix.patch changes gone.c, which the package's source does not have at level 0 (patch -p0)") }
  end
end
