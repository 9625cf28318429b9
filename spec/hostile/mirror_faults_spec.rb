# frozen_string_literal: true

require "spec_helper"

# `relspec mirror` after a fault (issue 46 case 8): a run killed (SIGKILL)
# while reprepro included packages leaves reprepro's lock, db/lockfile,
# which no process holds; every later reprepro waited for it (301 s) and
# then failed. The next run removes it as publish does (one rule:
# Publish::StaleRepreproLock), says so, and updates the mirror. A real
# release repository and a real distribution archive (reprepro), the
# mirror checked statically (--no-install: no mmdebstrap).
RSpec.describe "relspec mirror after a killed run" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-mirror-faults")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: ["bookworm"], architectures: ["amd64"])
                        .add("rock-m-one", "1.0-1", codename: "bookworm", arch: "amd64")
    AptRepositoryBuilder.new(File.join(@dir, "debian"), codenames: ["bookworm"], architectures: ["amd64"])
                        .add("libfoo1", "2.0-1", codename: "bookworm", arch: "amd64")
    File.write(File.join(@dir, "specs", "m.yml"), <<~YAML)
      release: m
      workspace: ../ws
      targets: { bookworm: [amd64] }
      repository: { path: ../repo, trusted: true }
      distributions:
        bookworm: { archive: { path: ../debian, trusted: true } }
    YAML
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  # A run of at most 60 s: the one that waits on the lock fails here
  # instead of after reprepro's 300 s.
  def mirror(out)
    relspec("mirror", "specs/m.yml", "--out", out, "--no-install", "--quiet", chdir: @dir, within: %w[timeout 60])
  end

  it "removes reprepro's stale lock no process holds, says so, and updates the mirror" do
    out = File.join(@dir, "mirror")
    first = mirror(out)
    expect(first.exit_code).to eq(0), first.stderr
    lock = File.join(out, "db", "lockfile")
    File.write(lock, "") # what a reprepro killed while it included packages leaves
    AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: ["bookworm"], architectures: ["amd64"])
                        .add("rock-m-two", "1.0-1", codename: "bookworm", arch: "amd64", depends: "libfoo1")
    run = mirror(out)
    expect([run.exit_code, run.stderr]).to eq([0, "removed reprepro's stale lock #{lock} (no reprepro uses the " \
                                                  "repository: one was killed before it could remove it)\n"])
    expect(run.stdout).to include("complete — 3 packages (2 of the release", "changes: 2 added (0.0 MB), 0 removed, 1 kept")
    expect(File.exist?(lock)).to be(false)
    expect(File.read(File.join(out, "dists", "bookworm", "main", "binary-amd64", "Packages")))
      .to include("Package: rock-m-two\n", "Package: libfoo1\n")
  end
end
