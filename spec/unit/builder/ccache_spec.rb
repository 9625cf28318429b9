# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/ccache"

# The compiler cache's folder and sbuild configuration lines, in a
# temporary folder with /etc/subuid and /etc/subgid as files (the real
# bind into a chroot: spec/relspec/builder/sbuild_spec.rb).
RSpec.describe Relspec::Builder::Ccache do
  around do |example|
    Dir.mktmpdir("ccache-unit") do |dir|
      @dir = dir
      File.write(File.join(dir, "subuid"), "alice:200000:65536\nroot:100000:65536\n")
      File.write(File.join(dir, "subgid"), "root:300000:65536\n")
      example.run
    end
  end

  def from(env, uid: 0, user: "root")
    described_class.from_environment(env, uid: uid, user: user, subuid: File.join(@dir, "subuid"),
                                          subgid: File.join(@dir, "subgid"))
  end

  it "is root's by default, owned by root's first subordinate uid and gid; off for others or when asked" do
    ccache = from({})
    expect([ccache.dir, ccache.owner]).to eq([described_class::DEFAULT_DIR, [100_000, 300_000]])
    expect(from({ "RELSPEC_CCACHE" => "/srv/cc/../ccache" }).dir).to eq("/srv/ccache")
    expect(from({ "RELSPEC_CCACHE" => "off" })).to be_nil
    expect(from({}, uid: 1000, user: "alice")).to be_nil
  end

  it "refuses a relative folder, a folder for a normal user and a missing or broken id range" do
    expect { from({ "RELSPEC_CCACHE" => "cc" }) }
      .to raise_error(Relspec::BuildError, 'RELSPEC_CCACHE=cc: not an absolute folder (or "off")')
    expect { from({ "RELSPEC_CCACHE" => "/cc" }, uid: 1000, user: "alice") }
      .to raise_error(Relspec::BuildError, /needs relspec to run as root .* set RELSPEC_CCACHE=off\z/)
    expect { from({}, user: "nobody").owner }
      .to raise_error(Relspec::BuildError, "no subordinate ids of nobody in #{@dir}/subuid, which sbuild's " \
                                           "unshare mode needs")
    File.write(File.join(@dir, "subgid"), "root:x:1\n")
    expect { from({}).owner }.to raise_error(Relspec::BuildError, "#{@dir}/subgid: the entry of root is not a number")
  end

  it "makes the folder closed to all but the build user and says sbuild's lines for it" do
    dir = File.join(@dir, "cache", "ccache")
    ccache = described_class.new(dir, owner: [Process.uid, Process.gid])
    lines = ccache.config_lines
    expect(File.stat(dir).mode & 0o777).to eq(0o700)
    expect(File.stat(File.dirname(dir)).mode & 0o777).to eq(0o755)
    expect(lines).to eq(
      ["$unshare_bind_mounts = [ { directory => '#{dir}', mountpoint => '/var/cache/ccache' } ];",
       "$build_environment = { 'CCACHE_DIR' => '/var/cache/ccache', 'CCACHE_BASEDIR' => '/build', " \
       "'CCACHE_MAXSIZE' => '5G' };",
       "$path = '/usr/lib/ccache:/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin:/usr/games';",
       "$manual_depends = ['ccache'];"]
    )
    # a folder someone opened is closed again
    File.chmod(0o777, dir)
    described_class.new(dir, owner: [Process.uid, Process.gid]).config_lines
    expect(File.stat(dir).mode & 0o777).to eq(0o700)
  end

  it "quotes the folder for Perl" do
    dir = File.join(@dir, "it's\\here")
    lines = described_class.new(dir, owner: [Process.uid, Process.gid]).config_lines
    expect(lines.first).to include("directory => '#{@dir}/it\\'s\\\\here'")
  end

  it "gives an empty folder to the build user" do
    skip "giving a folder to another uid needs root" unless Process.uid.zero?

    dir = File.join(@dir, "ccache")
    Dir.mkdir(dir)
    described_class.new(dir, owner: [100_123, 100_456]).config_lines
    expect([File.stat(dir).uid, File.stat(dir).gid]).to eq([100_123, 100_456])
  end

  # Issue 46, case 15: an empty folder of another user was chowned to the
  # build user and closed (0700), taking it from its owner.
  it "refuses an empty folder of another user instead of giving it to the build user" do
    skip "a folder of another uid needs root" unless Process.uid.zero?

    dir = File.join(@dir, "theirs")
    Dir.mkdir(dir, 0o755)
    File.chown(4242, 4242, dir)
    expect { described_class.new(dir, owner: [100_123, 100_456]).config_lines }
      .to raise_error(Relspec::BuildError, "ccache folder #{dir} belongs to uid 4242, not to the uid sbuild's build " \
                                           "user has here (100123): chown -R 100123:100456 it, or remove it")
    expect([File.stat(dir).uid, File.stat(dir).gid, File.stat(dir).mode & 0o777]).to eq([4242, 4242, 0o755])
  end

  it "gives the build user back what root made in its folder (ccache -z run by root), links included, not their targets" do
    skip "files of another uid need root" unless Process.uid.zero?

    dir = File.join(@dir, "ccache")
    FileUtils.mkdir_p(File.join(dir, "3", "b"))
    File.write(File.join(dir, "3", "b", "stats"), "")
    outside = File.join(@dir, "outside")
    File.write(outside, "")
    File.symlink(outside, File.join(dir, "3", "link"))
    File.chown(100_123, 100_456, dir)
    described_class.new(dir, owner: [100_123, 100_456]).config_lines
    owners = Dir.glob("#{dir}/**/*", File::FNM_DOTMATCH).map { |path| [File.lstat(path).uid, File.lstat(path).gid] }
    expect(owners.uniq).to eq([[100_123, 100_456]])
    expect(File.stat(outside).uid).to eq(0)
  end

  it "refuses a folder of another owner that holds files, and what is no folder" do
    dir = File.join(@dir, "ccache")
    Dir.mkdir(dir)
    File.write(File.join(dir, "f"), "")
    other = Process.uid + 1
    expect { described_class.new(dir, owner: [other, 0]).config_lines }
      .to raise_error(Relspec::BuildError, "ccache folder #{dir} belongs to uid #{Process.uid}, not to the uid " \
                                           "sbuild's build user has here (#{other}): chown -R #{other}:0 it, or remove it")
    link = File.join(@dir, "link")
    File.symlink(dir, link)
    expect { described_class.new(link, owner: [Process.uid, 0]).config_lines }
      .to raise_error(Relspec::BuildError, /\Accache folder #{link} is not a folder/)
  end
end
