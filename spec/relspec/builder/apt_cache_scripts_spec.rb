# frozen_string_literal: true

require "spec_helper"
require "open3"
require "tmpdir"
require "relspec/builder/apt_cache"

# The shell lines the apt download cache runs in each sbuild chroot, run
# here by sh on folders standing in for the bound cache and apt's archives
# (in a real chroot: spec/relspec/builder/sbuild_spec.rb).
RSpec.describe "apt download cache scripts" do
  around do |example|
    Dir.mktmpdir("apt-cache-scripts") do |dir|
      @kept = File.join(dir, "kept")
      @archives = File.join(dir, "archives")
      FileUtils.mkdir_p([@kept, @archives])
      example.run
    end
  end

  def sh(script)
    output, status = Open3.capture2e("sh", "-c", script)
    expect(status).to be_success, output
    output
  end

  def link(archives = @archives)
    sh(Relspec::Builder::AptCache.link_script(@kept, archives))
  end

  def keep(archives = @archives)
    sh(Relspec::Builder::AptCache.keep_script(@kept, archives))
  end

  it "links each kept .deb into apt's archives, and nothing else" do
    File.write(File.join(@kept, "cmake_3.25.1-1_amd64.deb"), "cmake")
    File.write(File.join(@kept, "libc6_2.36-9%3a1_amd64.deb"), "libc6")
    # what a killed build's copy left, and no .deb
    File.write(File.join(@kept, ".make_4.3-4.1_amd64.deb.AbC123"), "half")
    File.write(File.join(@kept, "notes"), "")
    link
    expect(Dir.children(@archives).sort).to eq(%w[cmake_3.25.1-1_amd64.deb libc6_2.36-9%3a1_amd64.deb])
    expect(File.readlink(File.join(@archives, "cmake_3.25.1-1_amd64.deb"))).to eq(File.join(@kept, "cmake_3.25.1-1_amd64.deb"))
  end

  it "links nothing from an empty cache" do
    link
    expect(Dir.children(@archives)).to eq([])
  end

  it "keeps what apt downloaded, not the links it was given nor sbuild's own package, and leaves no temporary behind" do
    File.write(File.join(@kept, "cmake_1_amd64.deb"), "cmake")
    link
    File.write(File.join(@archives, "pkg-config_1_amd64.deb"), "pkg-config")
    File.write(File.join(@archives, "lock"), "")
    File.write(File.join(@archives, "sbuild-build-depends-main-dummy_0.invalid.0_amd64.deb"), "this build's")
    keep
    expect(Dir.children(@kept).sort).to eq(%w[cmake_1_amd64.deb pkg-config_1_amd64.deb])
    expect(File.read(File.join(@kept, "pkg-config_1_amd64.deb"))).to eq("pkg-config")
    expect(File.symlink?(File.join(@kept, "cmake_1_amd64.deb"))).to be(false)
    # nothing downloaded: nothing to do
    FileUtils.rm_rf(Dir.glob("#{@archives}/*"))
    keep
    expect(Dir.children(@kept).sort).to eq(%w[cmake_1_amd64.deb pkg-config_1_amd64.deb])
  end

  it "never shows a half-written .deb, also when two builds keep the same one at once" do
    others = File.join(File.dirname(@archives), "others")
    Dir.mkdir(others)
    big = "a" * 20_000_000
    File.write(File.join(@archives, "big_1_amd64.deb"), big)
    File.write(File.join(others, "big_1_amd64.deb"), big)
    kept = File.join(@kept, "big_1_amd64.deb")
    sizes = []
    3.times do
      FileUtils.rm_f(kept)
      threads = [@archives, others].map { |archives| Thread.new { keep(archives) } }
      # what another build's link_script would find meanwhile
      sizes << (File.size?(kept) || 0) while threads.any?(&:alive?)
      threads.each(&:join)
      expect(Dir.children(@kept)).to eq(["big_1_amd64.deb"])
      expect(File.size(kept)).to eq(big.size)
    end
    expect(sizes.uniq - [0, big.size]).to eq([])
  end

  it "says when it cannot keep a .deb, and the build goes on" do
    FileUtils.rm_rf(@kept)
    File.write(@kept, "")
    File.write(File.join(@archives, "cmake_1_amd64.deb"), "cmake")
    expect(keep).to include("relspec: could not keep cmake_1_amd64.deb in the apt download cache")
  end
end
