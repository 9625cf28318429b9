# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/unpack_dir"

# Where sbuild unpacks a build's chroot: a folder standing in for /dev/shm,
# /proc/meminfo as a file and the tmpfs's free bytes as a value (df is a
# child process, which the unit layer refuses).
RSpec.describe Relspec::Builder::UnpackDir do
  around do |example|
    Dir.mktmpdir("unpack-dir") do |dir|
      @dir = dir
      @shm = File.join(dir, "shm")
      Dir.mkdir(@shm)
      example.run
    end
  end

  def unpack_dir(available_kib:, free:)
    meminfo = File.join(@dir, "meminfo")
    File.write(meminfo, "MemTotal:       24000000 kB\nMemAvailable:   #{available_kib} kB\n")
    described_class.new(shm: @shm, meminfo: meminfo, needed: 1024**3, free_bytes: ->(_dir) { free })
  end

  it "puts the chroot on tmpfs through SBUILD_CONFIG, in one folder per relspec process" do
    dir = unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3))
    env = dir.environment
    config = env.fetch("SBUILD_CONFIG")
    root = File.dirname(config)
    expect(File.dirname(root)).to eq(@shm)
    expect(Relspec::Temporaries.owner(File.basename(root)).first).to eq(Process.pid)
    expect(File.read(config)).to eq("$unshare_tmpdir_template = '#{root}/chroot.XXXXXXXXXX';\n1;\n")
    expect(File.stat(root).mode & 0o777).to eq(0o755)
    expect(dir.environment).to eq(env)
    expect(Dir.children(@shm)).to eq([File.basename(root)])
    # a build's chroot that sbuild could not remove (its sbuild was killed)
    FileUtils.mkdir_p(File.join(root, "chroot.AAAA", "usr"))
    dir.close
    expect(Dir.children(@shm)).to eq([])
  end

  it "adds more lines (ccache's) to the file, also when the chroot goes to disk" do
    extra = ["$path = '/usr/lib/ccache:/usr/bin';"]
    tmpfs = unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3))
    config = tmpfs.environment(extra).fetch("SBUILD_CONFIG")
    root = File.dirname(config)
    expect(File.read(config)).to eq("$unshare_tmpdir_template = '#{root}/chroot.XXXXXXXXXX';\n#{extra.first}\n1;\n")
    tmpfs.close
    disk = unpack_dir(available_kib: 512 * 1024, free: 2 * (1024**3))
    config = disk.environment(extra).fetch("SBUILD_CONFIG")
    expect(File.read(config)).to eq("#{extra.first}\n1;\n")
    expect(File.dirname(config, 2)).to eq(@shm)
    disk.close
    expect(Dir.children(@shm)).to eq([])
  end

  it "writes the lines to a folder of its own where there is no tmpfs" do
    FileUtils.rm_rf(@shm)
    dir = unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3))
    config = dir.environment(["1;"]).fetch("SBUILD_CONFIG")
    expect(File.read(config)).to eq("1;\n1;\n")
    dir.close
    expect(File.exist?(config)).to be(false)
  end

  it "removes what a killed relspec left there before making its own folder" do
    left = File.join(@shm, ".sbuild.relspec-999999999-1-0123abcd")
    FileUtils.mkdir_p(File.join(left, "chroot.AAAA", "usr"))
    unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3)).environment
    expect(File.exist?(left)).to be(false)
  end

  it "leaves sbuild on disk when tmpfs or memory is short, or unknown" do
    expect(unpack_dir(available_kib: 512 * 1024, free: 2 * (1024**3)).environment).to eq({})
    expect(unpack_dir(available_kib: 2 * 1024 * 1024, free: 1024).environment).to eq({})
    expect(unpack_dir(available_kib: 2 * 1024 * 1024, free: nil).environment).to eq({})
    FileUtils.rm_rf(@shm)
    expect(unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3)).environment).to eq({})
    expect(Dir.exist?(@shm)).to be(false)
  end

  it "gives folders on tmpfs when there is room, else on disk, and removes both when closed" do
    dir = unpack_dir(available_kib: 2 * 1024 * 1024, free: 2 * (1024**3))
    layers = dir.folder("bookworm-amd64")
    expect(File.dirname(layers, 2)).to eq(@shm)
    expect(dir.folder("bookworm-amd64")).to eq(layers)
    short = unpack_dir(available_kib: 512 * 1024, free: 2 * (1024**3))
    disk = short.folder("bookworm-amd64")
    expect(File.dirname(disk, 2)).to eq(Dir.tmpdir)
    expect(File.stat(File.dirname(disk)).mode & 0o777).to eq(0o755)
    [dir, short].each(&:close)
    expect([layers, disk].map { |path| File.exist?(path) }).to eq([false, false])
  end
end
