# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/chroot_layers"

# A target's chroot laid out in layers, in a temporary folder with this
# user's ids standing in for the subordinate ones (the commands run for
# real in spec/relspec/builder/sbuild_spec.rb).
RSpec.describe Relspec::Builder::ChrootLayers do
  around do |example|
    Dir.mktmpdir("chroot-layers-unit") { |dir| @dir = dir and example.run }
  end

  let(:ids) { { uids: [Process.uid, 1], gids: [Process.gid, 1] } }

  it "reads a subordinate range" do
    file = File.join(@dir, "subuid")
    File.write(file, "alice:200000:1000\nroot:100000:65536\n")
    expect(described_class.range(file, "root")).to eq([100_000, 65_536])
    expect { described_class.range(file, "bob") }.to raise_error(Relspec::BuildError, /no subordinate ids of bob/)
  end

  it "gives each build a layer of its own, removed when the build ends, also when it fails" do
    layers = described_class.new("/c/bookworm-amd64.tar.zst", @dir, **ids)
    seen = []
    layers.layer do |upper, work, merged|
      expect([upper, work, merged].map { |path| File.directory?(path) }).to eq([true, true, true])
      expect(File.stat(upper).mode & 0o777).to eq(0o755)
      seen << File.dirname(upper)
      layers.layer { |other, *| seen << File.dirname(other) }
    end
    expect { layers.layer { |upper, *| seen << File.dirname(upper) and raise "build failed" } }.to raise_error("build failed")
    expect(seen.uniq.size).to eq(3)
    expect(seen.map { |path| File.exist?(path) }).to eq([false, false, false])
  end

  it "wraps sbuild into a mount namespace with the overlay, and binds it first as the chroot's root" do
    layers = described_class.new("/c/t.tar.zst", @dir, **ids)
    command = layers.wrap(%w[sbuild x.dsc], "/l", "/u", "/w", "/m")
    expect(command).to eq(["unshare", "--mount", "--propagation", "private", "--", "sh", "-c",
                           'mount -t overlay overlay -o "lowerdir=$1,upperdir=$2,workdir=$3" "$4" && shift 4 && exec "$@"',
                           "sh", "/l", "/u", "/w", "/m", "sbuild", "x.dsc"])
    expect(layers.config_lines("/l/it's/merged")).to eq(
      ["unshift @{$unshare_bind_mounts}, { directory => '/l/it\\'s/merged', mountpoint => '/' };",
       # what a throw-away layer makes useless (the lists were refreshed in the lower layer)
       "$apt_update = 0;", "$purge_build_directory = 'never';", "$purge_session = 'never';",
       # sbuild's empty session folder goes with the layer
       "$unshare_tmpdir_template = '/l/it\\'s/session.XXXXXXXXXX';"]
    )
    empty = layers.empty_tarball
    expect(File.binread(empty)).to eq("\0" * 1024)
  end

  it "unpacks the lower layer once, with the tarball on stdin" do
    tool = Struct.new(:runs) do
      def run(*args, **options)
        runs << [args, options]
      end
    end.new([])
    layers = described_class.new("/c/t.tar.zst", @dir, **ids)
    lower = layers.lower(tool, "rock-a", "/log")
    expect(layers.lower(tool, "rock-b", "/log")).to eq(lower)
    expect(tool.runs.size).to eq(2)
    (source, command), options = tool.runs.first
    expect([source, options]).to eq(["rock-a", { log: "/log", stdin: "/c/t.tar.zst", name: "unpacking the chroot" }])
    expect(command.last(2)).to eq(["sh", lower])
    expect(command[-3]).to include("zstd -dc | tar -C \"$1\" -x --numeric-owner --exclude=./dev/urandom")
    # its package lists refreshed once, as the chroot's root, for every build on it
    (source, command), options = tool.runs.last
    expect([source, options]).to eq(["rock-a", { log: "/log", name: "refreshing the chroot's package lists" }])
    expect(command.first(4)).to eq(["unshare", "--user", "--map-users=#{Process.uid},0,1", "--map-groups=#{Process.gid},0,1"])
    expect(command).to include("--mount", "--pid", "--fork")
    expect(command.last(2)).to eq(["sh", lower])
    expect(command[-3]).to end_with('exec chroot "$1" apt-get -o Acquire::Languages=none update')
    expect(command[-3]).to start_with(described_class::SYSTEM_MOUNTS)
    expect(File.directory?(lower)).to be(true)
  end

  it "refuses a folder overlayfs cannot take" do
    expect { described_class.new("/c/t.tar.zst", "/tmp/a,b", **ids) }
      .to raise_error(Relspec::BuildError, "cannot lay a chroot out in /tmp/a,b: overlayfs takes no ',', ':' or '\\' " \
                                           "in its folders")
  end
end
