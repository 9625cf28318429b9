# frozen_string_literal: true

require "spec_helper"
require_relative "../support/git_project"

# Repository data `relspec osdeps package-set` would hand to users' root
# apt-get (issue 33): an osdeps file of the published repository whose
# Debian names are options, shell or apt syntax, and a repository URL that
# would add an apt line. Each is refused naming the file and the entry,
# exit 1, and no package set is written. The repository is a folder as
# `relspec publish` leaves it (its Packages index and osdeps file).
RSpec.describe "relspec osdeps package-set on hostile repository data", :tmpdir do
  def publish(osdeps, url: "https://example.org/r/a")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "a.yml"),
               "release: a\ntargets: { bookworm: [amd64] }\n" \
               "repository:\n  url: #{url.inspect}\n  path: ../repo\n  trusted: true\n")
    FileUtils.mkdir_p(File.join(@dir, "repo", "dists", "bookworm", "main", "binary-amd64"))
    File.write(File.join(@dir, "repo", "dists", "bookworm", "main", "binary-amd64", "Packages"), "")
    FileUtils.mkdir_p(File.join(@dir, "repo", "osdeps"))
    File.write(File.join(@dir, "repo", "osdeps", "a-amd64.yml"), osdeps)
  end

  def refused
    run = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(Dir.exist?(File.join(@dir, "package-set"))).to be(false)
    expect(Dir.glob("package-set*", base: @dir)).to eq([])
    run.stderr
  end

  def entry(deb)
    "base/cmake:\n  debian:\n    12,bookworm: #{deb.inspect}\n"
  end

  it "refuses a Debian name that apt would take as an option" do
    publish(entry("-oDPkg::Pre-Invoke::=touch /tmp/pwned"))
    expect(refused).to eq(
      "repo/osdeps/a-amd64.yml: error[package-set-osdeps]: base/cmake: \"-oDPkg::Pre-Invoke::=touch /tmp/pwned\" is " \
      "not a Debian package name (lowercase letters, digits, + - ., not starting with - or .)\n1 error in 1 file\n"
    )
  end

  it "refuses Debian names with spaces or shell syntax" do
    publish(entry("rock-a rock-b") + entry("rock-a;reboot").sub("base/cmake", "base/types") +
            entry("$(reboot)").sub("base/cmake", "base/logging"))
    expect(refused.lines.grep(/error\[package-set-osdeps\]/).map { |line| line[%r{: (base/\w+: "[^"]+")}, 1] })
      .to eq(['base/cmake: "rock-a rock-b"', 'base/logging: "$(reboot)"', 'base/types: "rock-a;reboot"'])
  end

  it "refuses an osdeps file that is not a mapping of packages" do
    publish("- rock-a\n")
    expect(refused).to eq("repo/osdeps/a-amd64.yml: error[package-set-osdeps]: is not a mapping of packages\n1 error in 1 file\n")
  end

  it "refuses a repository URL with a newline that would add an apt line" do
    publish(entry("rock-a-base-cmake"), url: "https://example.org/r/a\ndeb [trusted=yes] http://evil.example/a")
    expect(refused).to eq("specs/a.yml:4:8: error[repository-url]: url \"https://example.org/r/a\\ndeb [trusted=yes] " \
                          "http://evil.example/a\" is not a valid URL\n1 error in 1 file\n")
  end

  it "writes a package set of a well-formed repository (the cases above differ from it in one entry)" do
    publish(entry("rock-a-base-cmake"))
    run = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(run.stderr).to match(/\Awrote package-set \((\d+) of \1 files written, 0 removed\)\n\z/)
    expect(File.read(File.join(@dir, "package-set", "data", "a-amd64.yml"))).to eq(entry("rock-a-base-cmake"))
  end

  # The maintainer's recipe (docs/releasing.md): the package set is a git
  # repository, regenerated after each publish.
  it "keeps the git history and the maintainer's files of its folder, says unchanged, removes only its own stale files" do
    publish(entry("rock-a-base-cmake"))
    set = File.join(@dir, "package-set")
    run = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(run.exit_code).to eq(0)
    File.write(File.join(set, "README.md"), "the maintainer's\n")
    File.write(File.join(set, "data", "old-amd64.yml"), "a release no longer published\n")
    GitProject.init(set)
    GitProject.commit_all(set, "demo releases")

    second = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(second.stderr).to match(/\Awrote package-set \(0 of \d+ files written, 1 removed\)\n\z/)
    third = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(third.stderr).to match(/\Aunchanged package-set \(\d+ files\)\n\z/)
    expect(GitProject.git(set, "log", "--format=%s")).to eq("demo releases\n")
    expect(GitProject.git(set, "status", "--porcelain")).to eq(" D data/old-amd64.yml\n")
    expect(File.read(File.join(set, "README.md"))).to eq("the maintainer's\n")
    # the shipped files with non-ASCII text compare equal byte for byte
    expect(Dir.glob("lib/**/*.rb", base: set).any? { |path| !File.binread(File.join(set, path)).ascii_only? }).to be(true)
  end

  it "refuses to write through a symbolic link in its folder" do
    publish(entry("rock-a-base-cmake"))
    FileUtils.mkdir_p(File.join(@dir, "package-set"))
    FileUtils.mkdir_p(File.join(@dir, "elsewhere"))
    File.symlink(File.join(@dir, "elsewhere"), File.join(@dir, "package-set", "data"))
    run = relspec("osdeps", "package-set", "--out", "package-set", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: package-set/data is a symbolic link: the package set writes its own " \
                             "files only, remove it or choose another --out\n")
    expect(Dir.children(File.join(@dir, "elsewhere"))).to eq([])
  end
end
