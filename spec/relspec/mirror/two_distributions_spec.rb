# frozen_string_literal: true

require "spec_helper"

# `relspec mirror` of a release built for two distributions (issue 44 item
# 4): one mirror holds both codenames, each with its own builds and its own
# distribution's packages, and `--target` makes a mirror of one. A run with
# `--target` on a mirror that holds the other target too used to rewrite
# conf/distributions without it, and reprepro's clearvanished then dropped
# that distribution's packages from the mirror: it is refused, and the
# mirror is left as it was. A real release repository and real distribution
# archives (reprepro), the mirror checked statically (--no-install: no
# mmdebstrap).
RSpec.describe "relspec mirror of a release for bookworm and trixie" do
  CODENAMES = %w[bookworm trixie].freeze

  before(:all) do
    @dir = Dir.mktmpdir("relspec-mirror-two")
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    repo = AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: CODENAMES, architectures: ["amd64"])
    debian = AptRepositoryBuilder.new(File.join(@dir, "debian"), codenames: CODENAMES, architectures: ["amd64"])
    { "bookworm" => "2.36-9", "trixie" => "2.41-12" }.each do |codename, libc|
      repo.add("rock-m-one", "1.0-1~#{codename}", codename: codename, arch: "amd64", depends: "libc6 (>= #{libc})")
      debian.add("libc6", libc, codename: codename, arch: "amd64")
    end
    File.write(File.join(@dir, "specs", "m.yml"), <<~YAML)
      release: m
      workspace: ../ws
      targets: { bookworm: [amd64], trixie: [amd64] }
      repository: { path: ../repo, trusted: true }
      distributions:
        bookworm: { archive: { path: ../debian, trusted: true } }
        trixie: { archive: { path: ../debian, trusted: true } }
    YAML
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def mirror(out, *targets)
    relspec("mirror", "specs/m.yml", "--out", out, "--no-install", "--quiet",
            *targets.flat_map { |target| ["--target", target] }, chdir: @dir)
  end

  # Package => version of the mirror's index of +codename+ (nil: none).
  def held(out, codename)
    path = File.join(out, "dists", codename, "main", "binary-amd64", "Packages")
    return nil unless File.file?(path)

    File.read(path).split("\n\n").to_h { |stanza| [stanza[/^Package: (\S+)$/, 1], stanza[/^Version: (\S+)$/, 1]] }
  end

  # Every path below +dir+ => its bytes (false for a folder).
  def files(dir)
    Dir.glob("**/*", base: dir).sort.to_h { |path| [path, File.file?(File.join(dir, path)) && File.binread(File.join(dir, path))] }
  end

  it "holds each distribution's packages under its codename, and one target alone with --target" do
    both = File.join(@dir, "both")
    run = mirror(both)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(held(both, "bookworm")).to eq("rock-m-one" => "1.0-1~bookworm", "libc6" => "2.36-9")
    expect(held(both, "trixie")).to eq("rock-m-one" => "1.0-1~trixie", "libc6" => "2.41-12")
    expect(File.read(File.join(both, "m-mirror.list"))).to include(" bookworm main\n", " trixie main\n")
    verify = relspec("mirror", "verify", both, "--no-install", chdir: @dir)
    expect(verify.exit_code).to eq(0), verify.stdout
    expect(verify.stdout).to include("bookworm/amd64: complete", "trixie/amd64: complete")

    one = File.join(@dir, "trixie-only")
    run = mirror(one, "trixie/amd64")
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect([held(one, "bookworm"), held(one, "trixie")]).to eq([nil, { "rock-m-one" => "1.0-1~trixie", "libc6" => "2.41-12" }])
  end

  it "refuses to update one target of a mirror that holds both, and leaves the mirror as it was" do
    both = File.join(@dir, "kept")
    expect(mirror(both).exit_code).to eq(0)
    before = files(both)

    run = mirror(both, "trixie/amd64")
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: the mirror in kept holds bookworm/amd64 too: a run for trixie/amd64 " \
                             "alone would remove it from the mirror; give a --target for every target it holds " \
                             "(bookworm/amd64, trixie/amd64), or make the mirror of trixie/amd64 in another --out\n")
    after = files(both)
    expect(after).to eq(before)
    expect(held(both, "bookworm")).to include("rock-m-one" => "1.0-1~bookworm")

    again = mirror(both, "trixie/amd64", "bookworm/amd64")
    expect(again.exit_code).to eq(0), again.stdout + again.stderr
  end
end
