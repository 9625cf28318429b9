# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "open3"
require "zlib"
require "relspec/mirror/proof"
require_relative "../support/signing_key"

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
    @mirror = good_mirror
  end

  # A small good mirror, made offline from local reprepro repositories:
  # the release g (two packages) and a distribution archive with what they
  # need and a package nothing needs. Tests tamper with copies of it.
  def good_mirror
    release = AptRepositoryBuilder.new(File.join(@dir, "good"), codenames: ["bookworm"], architectures: ["amd64"])
    release.add("rock-g-one", "1.0-1", codename: "bookworm", arch: "amd64", depends: "libg1 (>= 1.0)")
    release.add("rock-g-two", "1.0-1", codename: "bookworm", arch: "all", depends: "rock-g-one")
    debian = AptRepositoryBuilder.new(File.join(@dir, "debian"), codenames: ["bookworm"], architectures: ["amd64"])
    debian.add("libg1", "1.2-1", codename: "bookworm", arch: "amd64")
    debian.add("unneeded", "1.0-1", codename: "bookworm", arch: "amd64")
    File.write(File.join(@dir, "specs", "g.yml"), <<~YAML)
      release: g
      workspace: ../ws
      targets: { bookworm: [amd64] }
      repository: { path: ../good, trusted: true }
      distributions:
        bookworm: { archive: { path: ../debian, trusted: true } }
    YAML
    out = File.join(@dir, "good-mirror")
    run = relspec("mirror", "specs/g.yml", "--out", out, "--no-install", "--quiet", chdir: @dir)
    raise "the good mirror was not made: #{run.stdout}#{run.stderr}" unless run.exit_code.zero?

    out
  end

  # A copy of the good mirror to tamper with.
  def copy_of_mirror(name)
    copy = File.join(@dir, name)
    FileUtils.cp_r(@mirror, copy, preserve: true)
    copy
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
    expect(run.stderr).to include("#{fake}/mirror.yml:5:5: error[mirror-manifest]: cannot read mirror.yml: " \
                                  "\"../../etc/amd64\" is not a target name")
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

  # issue 46, case 1: mirror.yml comes with the disk; a package name that
  # apt would read as an option is refused at its line before apt, dose or
  # anything else of the mirror runs.
  it "refuses a mirror.yml whose package name is an apt option, at its line, and runs nothing" do
    mirror = copy_of_mirror("option")
    marker = File.join(@dir, "option-ran")
    manifest = File.join(mirror, "mirror.yml")
    File.write(manifest, File.read(manifest).sub("- rock-g-two", "- \"-oDPkg::Pre-Invoke::=touch #{marker}\""))
    line = File.read(manifest).lines.index { |text| text.include?("Pre-Invoke") } + 1
    [[], ["--no-install"]].each do |options|
      run = relspec("mirror", "verify", mirror, *options, chdir: @dir)
      expect([run.exit_code, run.stdout]).to eq([1, ""])
      expect(run.stderr).to start_with("#{manifest}:#{line}:7: error[mirror-manifest]: cannot read mirror.yml: " \
                                       "\"-oDPkg::Pre-Invoke::=touch #{marker}\" is not a Debian package name")
    end
    expect(File.exist?(marker)).to be(false)
  end

  # The dynamic proof's install hook, as mmdebstrap runs it (sh -c, the
  # chroot as $1), with apt-get stood in by a recorder of its arguments (the
  # real one needs a chroot with a minimal system: the mirror CI test runs
  # it): whatever the names, they come after "--" and are not globbed.
  it "has apt install the release's packages after --" do
    bin = File.join(@dir, "recorder")
    FileUtils.mkdir_p(bin)
    File.write(File.join(bin, "apt-get"), "#!/bin/sh\nprintf '%s\\n' \"$@\" > \"$RECORD\"\n")
    File.chmod(0o755, File.join(bin, "apt-get"))
    record = File.join(@dir, "recorded")
    environment = { "PATH" => "#{bin}:#{ENV.fetch('PATH')}", "RECORD" => record, "MMDEBSTRAP_APT_CONFIG" => "/dev/null",
                    Relspec::Mirror::Proof::PACKAGES_VARIABLE => "-oDPkg::Pre-Invoke::=true rock-g-* rock-g-one" }
    _, status = Open3.capture2e(environment, "sh", "-c", Relspec::Mirror::Proof::INSTALL_HOOK, "sh", "/chroot", chdir: @dir)
    expect(status).to be_success
    expect(File.read(record).lines.map(&:chomp))
      .to eq(["--yes", "-oDPkg::Chroot-Directory=/chroot", "install", "--", "-oDPkg::Pre-Invoke::=true", "rock-g-*", "rock-g-one"])
  end

  # issue 46, case 11: verify checks every index against its Release file,
  # the forms of an index against each other (an unsigned mirror's Release
  # file can be rewritten too), and the pool against the indices both ways.
  it "finds a stanza dropped from Packages.gz, with or without the Release file rewritten to match" do
    mirror = copy_of_mirror("dropped")
    gz = File.join(mirror, "dists", "bookworm", "main", "binary-amd64", "Packages.gz")
    stanzas = Zlib.gunzip(File.binread(gz)).split("\n\n")
    dropped = Zlib.gzip("#{stanzas.reject { |stanza| stanza.start_with?("Package: rock-g-two\n") }.join("\n\n")}\n")
    File.binwrite(gz, dropped)
    run = relspec("mirror", "verify", mirror, "--no-install", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to include("bookworm/amd64: NOT complete", "\nfiles: failed (",
                                  "\n  dists/bookworm/main/binary-amd64/Packages.gz does not match the SHA256 of the Release file")

    ReleaseFileEditor.replace_index(mirror, "bookworm", "main/binary-amd64/Packages.gz", dropped)
    run = relspec("mirror", "verify", mirror, "--no-install", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to include("\n  dists/bookworm/main/binary-amd64/Packages.gz does not hold the packages of " \
                                  "Packages (without rock-g-two)\n")
  end

  it "finds pool files no index names, index entries whose file differs, and index files no Release file lists" do
    mirror = copy_of_mirror("extra")
    verified = relspec("mirror", "verify", mirror, "--no-install", chdir: @dir)
    expect([verified.exit_code, verified.stdout]).to match([0, /^files: passed \(\d+ index files checked against their Release file \(size, SHA256\), 3 pool files against the indices\)$/])

    FileUtils.mkdir_p(File.join(mirror, "pool", "main", "e", "extra"))
    File.write(File.join(mirror, "pool", "main", "e", "extra", "extra_1.0_amd64.deb"), "not a package")
    File.write(File.join(mirror, "dists", "bookworm", "main", "binary-amd64", "Packages.xz"), "")
    FileUtils.mkdir_p(File.join(mirror, "dists", "sid"))
    one = Dir.glob(File.join(mirror, "pool", "**", "rock-g-one_*.deb")).first
    File.write(one, "x", mode: "ab")
    run = relspec("mirror", "verify", mirror, "--no-install", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to include("\n  missing: #{one.delete_prefix("#{mirror}/")} (rock-g-one 1.0-1) is damaged (needed by rock-g-two)\n",
                                  "\n  dists/bookworm/main/binary-amd64/Packages.xz is not listed in the Release file\n",
                                  "\n  dists/sid is the distribution of no target of mirror.yml\n",
                                  "\n  pool/main/e/extra/extra_1.0_amd64.deb is in the pool but no index names it\n")
  end

  # issue 46, case 12: the distribution has a package of the release's name
  # in a higher version. The mirror is of the release as published: the
  # release's package stays, and the report says which one was pinned.
  it "keeps the release's package over a distribution's higher version of its name, and says so" do
    shadowing = AptRepositoryBuilder.new(File.join(@dir, "debian-shadowing"), codenames: ["bookworm"], architectures: ["amd64"])
    shadowing.add("libg1", "1.2-1", codename: "bookworm", arch: "amd64")
    shadowing.add("rock-g-one", "9.0-1", codename: "bookworm", arch: "amd64")
    FileUtils.mkdir_p(File.join(@dir, "shadowed"))
    File.write(File.join(@dir, "shadowed", "g.yml"),
               File.read(File.join(@dir, "specs", "g.yml")).sub("path: ../debian,", "path: ../debian-shadowing,"))
    out = File.join(@dir, "shadowed-mirror")
    run = relspec("mirror", "shadowed/g.yml", "--out", out, "--no-install", "--quiet", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(run.stdout).to include("bookworm/amd64: complete", "\n  pinned: rock-g-one 1.0-1 of g is kept; the distribution's " \
                                                              "9.0-1 (bookworm) is not mirrored\n")
    packages = File.read(File.join(out, "dists", "bookworm", "main", "binary-amd64", "Packages"))
    expect(packages.scan(/^Package: rock-g-one\nVersion: (.*)$/)).to eq([["1.0-1"]])
    expect(File.read(File.join(out, "VERIFIED.md"))).to include("- pinned: rock-g-one 1.0-1 of g is kept")
  end

  # A signed mirror (repository.sign_with) is checked with its own key: a
  # Release file changed after signing is refused, not read.
  it "checks a signed mirror's Release file with the mirror's key" do
    home = File.join(@dir, "gnupg")
    FileUtils.mkdir_p(home, mode: 0o700)
    key = SigningKey.new(home)
    FileUtils.mkdir_p(File.join(@dir, "signed"))
    File.write(File.join(@dir, "signed", "g.yml"), File.read(File.join(@dir, "specs", "g.yml"))
      .sub("repository: { path: ../good, trusted: true }", "repository: { path: ../good, trusted: true, sign_with: #{key.fingerprint} }"))
    out = File.join(@dir, "signed-mirror")
    run = relspec("mirror", "signed/g.yml", "--out", out, "--no-install", "--quiet", chdir: @dir, env: key.env)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    verify = relspec("mirror", "verify", out, "--no-install", chdir: @dir)
    expect([verify.exit_code, verify.stdout]).to match([0, /^files: passed/])

    in_release = File.join(out, "dists", "bookworm", "InRelease")
    File.write(in_release, File.read(in_release).sub(/^Label: .*$/, "Label: changed"))
    verify = relspec("mirror", "verify", out, "--no-install", chdir: @dir)
    expect(verify.exit_code).to eq(1)
    expect(verify.stdout).to match(%r{^files: failed .*\n  dists/bookworm/InRelease: signature check failed: BAD signature})
  ensure
    key&.stop
  end
end
