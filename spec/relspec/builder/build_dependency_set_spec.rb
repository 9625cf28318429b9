# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "securerandom"
require "relspec/builder/build_dependency_set"
require_relative "../../support/apt_repository_builder"
require_relative "../../support/private_apt"

# The set read from a real apt resolution: real .debs in a real reprepro
# repository, apt-get with its own lists and an empty dpkg status (a chroot
# with none of them), so that what apt would install is known.
RSpec.describe Relspec::Builder::BuildDependencySet do
  around do |example|
    Dir.mktmpdir("build-dependency-set") do |dir|
      @dir = dir
      example.run
    end
  end

  def resolve(depends, repository)
    status = File.join(@dir, "status")
    File.write(status, "")
    apt = PrivateApt.new(File.join(@dir, "apt-#{SecureRandom.hex(4)}"), [PrivateApt.source(repository.dir, "bookworm")],
                         machine_status: status)
    _, updated = apt.update
    expect(updated).to be_success
    output, status = Open3.capture2e("apt-get", *apt.options, *described_class.simulate_arguments(depends))
    expect(status).to be_success, output
    described_class.from_simulation(output, source: "test")
  end

  # A repository with what sbuild adds to every build.
  def core_repository
    repository = AptRepositoryBuilder.new(File.join(@dir, "repo"), codenames: %w[bookworm], architectures: %w[amd64])
    repository.add("build-essential", "12.9", codename: "bookworm", arch: "amd64")
    repository.add("fakeroot", "1.31-1.2", codename: "bookworm", arch: "amd64")
    repository
  end

  it "is exactly what apt installs for the Build-Depends and sbuild's own, and changes with a version" do
    repository = core_repository
    repository.add("rel-base", "2:0.5~rc1-1", codename: "bookworm", arch: "all")
    repository.add("rel-cmake", "1.0-1", codename: "bookworm", arch: "amd64", depends: "rel-base")
    repository.add("rel-unused", "1", codename: "bookworm", arch: "all")

    first = resolve(["rel-cmake (>= 1.0)", "rel-base [amd64] <!nocheck>"], repository)
    expect(first.install_arguments).to eq(["build-essential:amd64=12.9", "fakeroot:amd64=1.31-1.2",
                                           "rel-base:all=2:0.5~rc1-1", "rel-cmake:amd64=1.0-1"])
    expect(resolve(["rel-cmake"], repository)).to eq(first)
    expect(resolve(["rel-base"], repository)).not_to eq(first)

    repository.add("rel-cmake", "1.0-2", codename: "bookworm", arch: "amd64", depends: "rel-base")
    newer = resolve(["rel-cmake"], repository)
    expect(newer.install_arguments).to include("rel-cmake:amd64=1.0-2")
    expect(newer.key).not_to eq(first.key)
  end

  # A chroot's apt state in a folder: its sources, lists (apt-get update
  # with this machine's apt, as the lower layer's refresh) and dpkg status.
  def unpacked_root(repository)
    root = File.join(@dir, "root")
    %w[etc/apt/apt.conf.d etc/apt/preferences.d etc/apt/sources.list.d var/lib/apt/lists/partial var/lib/dpkg var/log/apt
       var/cache/apt/archives/partial].each { |sub| FileUtils.mkdir_p(File.join(root, sub)) }
    File.write(File.join(root, "etc/apt/sources.list"), "#{PrivateApt.source(repository.dir, 'bookworm')}\n")
    File.write(File.join(root, "var/lib/dpkg/status"), "")
    output, status = Open3.capture2e("apt-get", "-o", "Dir=#{root}/", "-o", "Debug::NoLocking=1", "update")
    expect(status).to be_success, output
    root
  end

  def tree(root)
    Dir.glob("**/*", File::FNM_DOTMATCH, base: root).sort.to_h do |path|
      stat = File.lstat(File.join(root, path))
      [path, [stat.mtime, stat.size]]
    end
  end

  it "simulates in an unpacked chroot with this machine's apt-get, writing nothing into it" do
    repository = core_repository
    repository.add("rel-cmake", "1.0-1", codename: "bookworm", arch: "amd64")
    root = unpacked_root(repository)
    before = tree(root)
    scratch = File.join(@dir, "scratch")
    output, status = Open3.capture2e(*described_class.simulate_command(root, scratch, ["rel-cmake"]))
    expect(status).to be_success, output
    expect(described_class.from_simulation(output, source: "test").install_arguments)
      .to eq(["build-essential:amd64=12.9", "fakeroot:amd64=1.31-1.2", "rel-cmake:amd64=1.0-1"])
    expect(tree(root)).to eq(before)
  end
end
