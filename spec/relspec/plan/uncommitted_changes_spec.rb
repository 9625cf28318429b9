# frozen_string_literal: true

require "spec_helper"
require "open3"

# Checkouts of a real git workspace holding changes beyond their commits:
# the release is made of the commits (the .orig is `git archive`), so plan
# says which packages lose what. Changes that are exactly the package set's
# patches, applied as autoproj applies them (`patch -p1 --forward`), are in
# the release (as quilt patches) and are not noted; untracked files are not
# the package's.
RSpec.describe "uncommitted changes in checkouts" do
  before(:all) do
    @base = Dir.mktmpdir("relspec-uncommitted")
    builder = WorkspaceBuilder.new(@base)
    files = { "CMakeLists.txt" => "project(x)\n", "src/a.c" => "int a;\n" }
    %w[clean changed patched patched_more].each do |name|
      builder.package(name, type: :cmake, date: "2020-06-01T10:00:00Z", files: files)
    end
    builder.metapackage("all", "clean", "changed", "patched", "patched_more")
    root = builder.create
    File.write(File.join(root, "autoproj", "fix.patch"), <<~PATCH)
      --- a/src/a.c
      +++ b/src/a.c
      @@ -1 +1 @@
      -int a;
      +int a = 1;
    PATCH
    File.write(File.join(root, "autoproj", "overrides.yml"), <<~YAML)
      overrides:
        - patched: { patches: [[$AUTOPROJ_ROOT/autoproj/fix.patch, 1]] }
        - patched_more: { patches: [[$AUTOPROJ_ROOT/autoproj/fix.patch, 1]] }
    YAML
    %w[patched patched_more].each do |name|
      _, status = Open3.capture2e("patch", "-p1", "--forward", "-i", File.join(root, "autoproj", "fix.patch"),
                                  chdir: File.join(root, "src", name))
      raise "patch failed in #{name}" unless status.success?
    end
    File.write(File.join(root, "src", "changed", "src", "a.c"), "int a = 2;\n")
    File.write(File.join(root, "src", "patched_more", "CMakeLists.txt"), "project(y)\n")
    # bad input: a checkout whose git configuration names a command git status would run
    _, status = Open3.capture2e("git", "-C", File.join(root, "src", "changed"), "config", "core.fsmonitor",
                                "touch #{File.join(@base, 'monitor-ran')}; false")
    raise "git config failed" unless status.success?

    # untracked: not the package's
    File.write(File.join(root, "src", "clean", "notes.txt"), "mine\n")
    FileUtils.mkdir_p(File.join(@base, "specs"))
    File.write(File.join(@base, "specs", "r.yml"), <<~YAML)
      release: r
      maintainer: Rock Packaging <rock@example.org>
      workspace: ../workspace
      select: [all]
      targets: { bookworm: [amd64] }
    YAML
  end

  after(:all) { FileUtils.rm_rf(@base) if @base }

  it "notes each checkout whose tracked files differ from its commit, beyond the package set's patches" do
    run = relspec("plan", "specs/r.yml", chdir: @base)
    expect(run.exit_code).to eq(0), run.stderr
    notes = run.stdout.lines.grep(/uncommitted/).map(&:strip)
    expect(notes).to eq(
      ["changed has uncommitted changes in its checkout (src/a.c): the release is made of its commit, without them",
       "patched_more has uncommitted changes in its checkout (CMakeLists.txt, src/a.c): the release is made of its " \
       "commit, without them (they are not exactly the package set's patches, which the release applies)"]
    )
    expect(File.exist?(File.join(@base, "monitor-ran"))).to be(false)
  end
end
