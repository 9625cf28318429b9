# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/apt_cache"
require "relspec/target"

# The apt download cache's folders and sbuild configuration lines, in a
# temporary folder (its scripts run for real in
# spec/relspec/builder/apt_cache_scripts_spec.rb, the cache in a real
# sbuild build in spec/relspec/builder/sbuild_spec.rb).
RSpec.describe Relspec::Builder::AptCache do
  around do |example|
    Dir.mktmpdir("apt-cache-unit") do |dir|
      @dir = dir
      File.write(File.join(dir, "subuid"), "root:100000:65536\n")
      File.write(File.join(dir, "subgid"), "root:100000:65536\n")
      example.run
    end
  end

  def cache(dir = File.join(@dir, "cache", "apt"))
    folder = Relspec::Builder::BuildUserFolder.new(dir, owner: [Process.uid, Process.gid], what: "apt download cache",
                                                        variable: described_class::VARIABLE)
    described_class.new(folder)
  end

  let(:target) { Relspec::Target.new("bookworm", "amd64") }

  it "is root's by default, in its own folder; off for others or when asked" do
    who = { subuid: File.join(@dir, "subuid"), subgid: File.join(@dir, "subgid") }
    expect(described_class.from_environment({}, uid: 0, user: "root", **who).dir).to eq("/var/cache/relspec/apt")
    expect(described_class.from_environment({ "RELSPEC_APT_CACHE" => "/srv/apt" }, uid: 0, user: "root", **who).dir)
      .to eq("/srv/apt")
    expect(described_class.from_environment({ "RELSPEC_APT_CACHE" => "off" }, uid: 0, user: "root", **who)).to be_nil
    expect(described_class.from_environment({}, uid: 1000, user: "alice", **who)).to be_nil
    expect { described_class.from_environment({ "RELSPEC_APT_CACHE" => "apt" }, uid: 0, user: "root", **who) }
      .to raise_error(Relspec::BuildError, 'RELSPEC_APT_CACHE=apt: not an absolute folder (or "off")')
    expect { described_class.from_environment({ "RELSPEC_APT_CACHE" => "/a" }, uid: 1000, user: "alice", **who) }
      .to raise_error(Relspec::BuildError, %r{\ARELSPEC_APT_CACHE=/a: apt download cache in sbuild's chroot needs})
  end

  it "binds a folder per target, closed to all but the build user, and links and keeps its .debs" do
    apt = cache
    lines = apt.config_lines(target)
    kept = File.join(@dir, "cache", "apt", "bookworm-amd64")
    expect(File.stat(kept).mode & 0o777).to eq(0o700)
    expect(File.stat(File.dirname(kept)).mode & 0o777).to eq(0o700)
    expect(lines).to eq(
      ["push @{$unshare_bind_mounts}, { directory => '#{kept}', mountpoint => '/var/cache/relspec-apt' };",
       "$apt_keep_downloaded_packages = 1;",
       "push @{$external_commands->{'chroot-setup-commands'}}, " \
       "'find /var/cache/relspec-apt -maxdepth 1 -type f -name \\'*.deb\\' -exec ln -sf -t /var/cache/apt/archives {} +';",
       "push @{$external_commands->{'starting-build-commands'}}, " \
       "'#{described_class.keep_script.gsub("'", "\\\\'")}';"]
    )
    # another target, another folder; the same target, the same one
    expect(apt.config_lines(Relspec::Target.new("trixie", "arm64")).first).to include("apt/trixie-arm64'")
    expect(apt.config_lines(target)).to eq(lines)
  end

  it "refuses a target's folder that is a link or a file" do
    apt = cache
    apt.prepare
    outside = File.join(@dir, "outside")
    Dir.mkdir(outside)
    File.symlink(outside, apt.target_dir(target))
    expect { apt.config_lines(target) }
      .to raise_error(Relspec::BuildError, "apt download cache folder #{apt.target_dir(target)} is not a folder")
    File.unlink(apt.target_dir(target))
    File.write(apt.target_dir(target), "")
    expect { apt.config_lines(target) }.to raise_error(Relspec::BuildError, /is not a folder\z/)
  end
end
