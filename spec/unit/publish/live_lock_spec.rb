# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/publish/live_lock"

# reprepro's lock on the live database, taken by publish (no reprepro runs
# here, so every lock file found is stale: StaleRepreproLock reads /proc).
RSpec.describe Relspec::Publish::LiveLock, :tmpdir do
  let(:lock) { described_class.new(@dir) }
  let(:path) { File.join(@dir, "db", "lockfile") }

  it "makes db/lockfile as reprepro does, and removes it and the db/ folder it made on release" do
    expect(lock.take).to be_nil
    expect(File.read(path)).to match(/\Arelspec publish #{Process.pid} \h{16}\n\z/)
    lock.release
    expect(File.exist?(File.join(@dir, "db"))).to be(false)
  end

  it "removes a stale lock file on the way and says which" do
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, "")
    File.write(File.join(@dir, "db", "packages.db"), "")
    expect(lock.take).to eq(path)
    lock.release
    expect(File.exist?(path)).to be(false)
    expect(File.exist?(File.join(@dir, "db", "packages.db"))).to be(true)
  end

  it "leaves a lock file that is not the one it took (a database switched in, then locked by a reprepro)" do
    lock.take
    File.delete(path)
    File.write(path, "another\n")
    lock.release
    expect(File.read(path)).to eq("another\n")
  end
end
