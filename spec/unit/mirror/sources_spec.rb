# frozen_string_literal: true

require_relative "../unit_helper"
require "digest"
require "relspec/release_specs"
require "relspec/target"
require "relspec/mirror/sources"

# What a release's mirror is seeded with, on repository folders written
# here (no reprepro): the release's own index and the Debian names of its
# published osdeps file, read for the target's system (Osdeps::Reader).
RSpec.describe Relspec::Mirror::Sources, :tmpdir do
  def repository(name, codename, packages)
    dir = File.join(@dir, name)
    text = packages.map do |package|
      "Package: #{package}\nVersion: 1.0-1\nArchitecture: amd64\nPriority: optional\n" \
        "Filename: pool/main/#{package[0]}/#{package}/#{package}_1.0-1_amd64.deb\nSize: 1\nSHA256: #{'0' * 64}\n"
    end.join("\n")
    FileUtils.mkdir_p(File.join(dir, "dists", codename, "main", "binary-amd64"))
    File.write(File.join(dir, "dists", codename, "main", "binary-amd64", "Packages"), text)
    File.write(File.join(dir, "dists", codename, "Release"),
               "Codename: #{codename}\nArchitectures: amd64\nComponents: main\nSHA256:\n " \
               "#{Digest::SHA256.hexdigest(text)} #{text.bytesize} main/binary-amd64/Packages\n")
    dir
  end

  def read(codename, osdeps)
    repository("repo", codename, ["rock-u-one"])
    repository("archive", codename, %w[rock-p-inherited unneeded])
    FileUtils.mkdir_p(File.join(@dir, "repo", "osdeps"))
    File.write(File.join(@dir, "repo", "osdeps", "u-amd64.yml"), osdeps) if osdeps
    File.write(File.join(@dir, "u.yml"), <<~YAML)
      release: u
      workspace: ws
      targets: { #{codename}: [amd64] }
      repository: { path: repo, trusted: true }
      distributions:
        #{codename}: { archive: { path: archive, trusted: true } }
    YAML
    described_class.new(Relspec::ReleaseSpec.resolve(File.join(@dir, "u.yml"))).read(Relspec::Target.parse("#{codename}/amd64"))
  end

  it "seeds an Ubuntu release with the inherited names its osdeps file gives for the target" do
    seeds = read("focal", "base/inherited:\n  ubuntu,debian:\n    20.04,focal: rock-p-inherited\n").seeds
    expect(seeds).to eq(%w[rock-p-inherited rock-u-one])
  end

  it "seeds with the release's own index when it publishes no osdeps file" do
    expect(read("bookworm", nil).seeds).to eq(["rock-u-one"])
  end

  it "refuses a name there that is not a Debian one, naming the file and the package" do
    expect { read("bookworm", "base/x:\n  debian:\n    12,bookworm: \"-oX=y\"\n") }
      .to raise_error(Relspec::RepositoryError, %r{repo/osdeps/u-amd64\.yml: base/x: "-oX=y" is not a Debian package name})
  end
end
