# frozen_string_literal: true

require "spec_helper"

# The release's published osdeps file seeds the mirror (inherited packages
# the release's own index does not hold), read as autoproj on the target's
# system reads it (Osdeps::Reader): an Ubuntu release's entries are keyed
# "ubuntu,debian", and were once not read at all. Real reprepro
# repositories, made offline.
RSpec.describe "relspec mirror's seeds from the osdeps file" do
  around do |example|
    Dir.mktmpdir("relspec-mirror-osdeps") do |dir|
      @dir = dir
      release = AptRepositoryBuilder.new(File.join(dir, "repo"), codenames: ["focal"], architectures: ["amd64"])
      release.add("rock-u-one", "1.0-1", codename: "focal", arch: "amd64")
      archive = AptRepositoryBuilder.new(File.join(dir, "ubuntu"), codenames: ["focal"], architectures: ["amd64"])
      archive.add("rock-p-inherited", "1.0-1", codename: "focal", arch: "amd64")
      archive.add("unneeded", "1.0-1", codename: "focal", arch: "amd64")
      FileUtils.mkdir_p([File.join(dir, "repo", "osdeps"), File.join(dir, "specs")])
      File.write(File.join(dir, "specs", "u.yml"), <<~YAML)
        release: u
        workspace: ../ws
        targets: { focal: [amd64] }
        repository: { path: ../repo, trusted: true }
        distributions:
          focal: { archive: { path: ../ubuntu, trusted: true } }
      YAML
      example.run
    end
  end

  def osdeps(inherited)
    File.write(File.join(@dir, "repo", "osdeps", "u-amd64.yml"),
               "base/one:\n  ubuntu,debian:\n    20.04,focal: rock-u-one\n" \
               "base/inherited:\n  ubuntu,debian:\n    20.04,focal: #{inherited}\n")
  end

  def mirrored
    File.read(File.join(@dir, "out", "dists", "focal", "main", "binary-amd64", "Packages")).scan(/^Package: (.*)$/).flatten.sort
  end

  it "mirrors the inherited package an Ubuntu release's osdeps file names" do
    osdeps("rock-p-inherited")
    run = relspec("mirror", "specs/u.yml", "--out", "out", "--no-install", "--quiet", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(mirrored).to eq(%w[rock-p-inherited rock-u-one])
  end

  it "refuses a name there that is not a Debian name, naming the file and the package" do
    osdeps('"-oX=y"')
    run = relspec("mirror", "specs/u.yml", "--out", "out", "--no-install", "--quiet", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("repo/osdeps/u-amd64.yml: base/inherited: \"-oX=y\" is not a Debian package name")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
  end
end
