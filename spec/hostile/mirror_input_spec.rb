# frozen_string_literal: true

require "spec_helper"
require "yaml"

# `relspec mirror` with bad input (issue 35): the command line, a folder
# that is not a mirror, a mirror.yml naming a path instead of a target, and
# a release repository whose signed-off index names a file outside the
# pool. Each is one message and exit 1, and nothing is read, fetched or
# written past the check.
RSpec.describe "relspec mirror with bad input" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-mirror")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    repository = File.join(@dir, "repo")
    builder = AptRepositoryBuilder.new(repository, codenames: ["bookworm"], architectures: ["amd64"])
    builder.add("rock-h-one", "1.0-1", codename: "bookworm", arch: "amd64")
    path = "main/binary-amd64/Packages"
    text = File.read(File.join(repository, "dists", "bookworm", path))
    ReleaseFileEditor.replace_index(repository, "bookworm", path, text.sub(/^Filename: .*$/, "Filename: ../../../etc/hostile.deb"))
    ReleaseFileEditor.keep_only(repository, "bookworm", "main/binary-amd64", path)
    File.write(File.join(@dir, "specs", "h.yml"), <<~YAML)
      release: h
      workspace: ../ws
      targets: { bookworm: [amd64] }
      repository: { path: ../repo, trusted: true }
      distributions:
        bookworm: { archive: { host: true } }
    YAML
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  it "needs --out for a spec and one folder for verify" do
    run = relspec("mirror", "specs/h.yml", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: relspec mirror SPEC needs --out DIR: the folder the mirror is made in\n"])
    run = relspec("mirror", "verify", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: relspec mirror verify takes one folder: relspec mirror verify DIR\n"])
  end

  it "refuses a folder that is not a mirror, and a mirror.yml naming a path as a target" do
    run = relspec("mirror", "verify", "nothing", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: nothing is not a mirror: it has no mirror.yml (make one with relspec mirror SPEC --out nothing)\n")

    fake = File.join(@dir, "fake")
    FileUtils.mkdir_p(fake)
    File.write(File.join(fake, "mirror.yml"), YAML.dump("release" => "h", "targets" => { "../../etc/amd64" => { "release" => [] } }))
    run = relspec("mirror", "verify", fake, chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("#{fake}/mirror.yml: ../../etc/amd64 is not a target name")
  end

  # Issue 46, case 5: --out naming a folder relspec did not make. The
  # release's own reprepro repository (a real one) and a folder with only a
  # conf/ are refused before anything is written; an empty folder is
  # adopted (the run then stops at the hostile index, as below).
  it "refuses to make a mirror in a folder it did not make, a reprepro repository included, and changes nothing" do
    repository = File.join(@dir, "repo")
    before = Dir.glob("**/*", base: repository).sort.to_h do |name|
      path = File.join(repository, name)
      [name, File.file?(path) ? File.binread(path) : :folder]
    end
    run = relspec("mirror", "specs/h.yml", "--out", "repo", chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: --out repo is not a mirror relspec made (it holds .debs, conf, db, … and " \
                             "no .relspec-mirror): relspec mirror makes a mirror in a new or empty folder and changes " \
                             "only the mirrors it made; choose another --out\n")
    after = Dir.glob("**/*", base: repository).sort.to_h do |name|
      path = File.join(repository, name)
      [name, File.file?(path) ? File.binread(path) : :folder]
    end
    expect(after).to eq(before)
    expect(system("reprepro", "-b", repository, "check", out: File::NULL, err: File::NULL)).to be(true)

    conf_only = File.join(@dir, "conf-only")
    FileUtils.mkdir_p(File.join(conf_only, "conf"))
    File.write(File.join(conf_only, "conf", "distributions"), "Codename: mine\n")
    run = relspec("mirror", "specs/h.yml", "--out", "conf-only", chdir: @dir)
    expect([run.exit_code, run.stderr]).to match([1, start_with("relspec: error: --out conf-only is not a mirror relspec made (it holds conf and")])
    expect(Dir.children(conf_only)).to eq(["conf"])
    expect(File.read(File.join(conf_only, "conf", "distributions"))).to eq("Codename: mine\n")

    empty = File.join(@dir, "empty")
    FileUtils.mkdir_p(empty)
    run = relspec("mirror", "specs/h.yml", "--out", "empty", chdir: @dir)
    expect([run.exit_code, run.stderr]).to match([1, include("is not a pool path")])
    expect(File.file?(File.join(empty, ".relspec-mirror"))).to be(true)
  end

  it "refuses an index whose Filename leaves the pool, before anything is fetched or written" do
    out = File.join(@dir, "mirror")
    run = relspec("mirror", "specs/h.yml", "--out", out, chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to match(%r{\Arelspec: error: .*repo \(bookworm/main/binary-amd64\), stanza 1 \(rock-h-one\): Filename "../../../etc/hostile.deb" is not a pool path\n\z})
    expect(Dir.exist?(File.join(out, "pool"))).to be(false)
  end
end
