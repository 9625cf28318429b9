# frozen_string_literal: true

require "spec_helper"
require "tmpdir"
require "relspec/publish/stale_reprepro_lock"

# reprepro's db/lockfile left by a killed reprepro is removed; one that a
# live reprepro may hold is kept. The processes are real: the real reprepro
# waiting for the lock, and shell scripts named reprepro (the kernel names a
# script's process after its file) that hold a file of the repository open.
RSpec.describe Relspec::Publish::StaleRepreproLock do
  around do |example|
    Dir.mktmpdir("relspec-stale-lock") do |dir|
      @dir = dir
      example.run
    ensure
      @pids&.each do |pid|
        Process.kill("KILL", pid)
        Process.wait(pid)
      rescue Errno::ESRCH, Errno::ECHILD
        nil
      end
    end
  end

  let(:repository) { File.join(@dir, "repo") }
  let(:lock) { File.join(repository, "db", "lockfile") }

  before do
    FileUtils.mkdir_p(File.join(repository, "conf"))
    FileUtils.mkdir_p(File.join(repository, "db"))
    File.write(File.join(repository, "conf", "distributions"), "Codename: bookworm\nArchitectures: amd64 source\nComponents: main\n")
    File.write(File.join(repository, "db", "packages.db"), "")
    File.write(lock, "")
  end

  # Starts +command+ in the background; waits until +ready+ holds.
  def start(*command, chdir: @dir, ready: -> { true })
    pid = Process.spawn(*command, chdir: chdir, out: File::NULL, err: File::NULL)
    (@pids ||= []) << pid
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 10
    sleep(0.02) until ready.call || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    pid
  end

  def script(name, body)
    path = File.join(@dir, "bin", name)
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, "#!/bin/sh\n#{body}\n")
    File.chmod(0o755, path)
    path
  end

  def fd_open?(pid)
    Dir.glob("/proc/#{pid}/fd/*").any? { |fd| File.readlink(fd).start_with?(repository) rescue false } # rubocop:disable Style/RescueModifier
  end

  it "removes a lock file no process holds, and says which" do
    expect(described_class.clear(repository)).to eq(lock)
    expect(File.exist?(lock)).to be(false)
  end

  it "answers nil when there is no lock file" do
    File.delete(lock)
    expect(described_class.clear(repository)).to be_nil
  end

  it "keeps the lock while the real reprepro, started by hand with a relative -b, waits for it" do
    pid = start("reprepro", "-b", "repo", "--waitforlock", "20", "export")
    sleep(0.5) # reprepro has met the lock and waits (10 s before its next try)
    expect(Process.waitpid(pid, Process::WNOHANG)).to be_nil
    expect(described_class.clear(repository)).to be_nil
    expect(File.exist?(lock)).to be(true)
  end

  it "keeps the lock while a process named reprepro has a file of the repository open" do
    pid = start(script("reprepro", "exec 3< #{repository}/db/packages.db\nsleep 30"), chdir: "/",
                                                                                      ready: -> { fd_open?(@pids.last) })
    expect(fd_open?(pid)).to be(true)
    expect(described_class.clear(repository)).to be_nil
    expect(File.exist?(lock)).to be(true)
  end

  it "keeps the lock while a process named reprepro works in the repository" do
    start(script("reprepro", "sleep 30"), chdir: repository)
    sleep(0.1)
    expect(described_class.clear(repository)).to be_nil
  end

  it "removes the lock when only other programs hold the repository's files, or reprepro works elsewhere" do
    start(script("other", "exec 3< #{repository}/db/packages.db\nsleep 30"), chdir: "/", ready: -> { fd_open?(@pids.last) })
    start(script("reprepro", "sleep 30"), chdir: "/")
    sleep(0.1)
    expect(described_class.clear(repository)).to eq(lock)
  end

  it "removes the lock when the reprepro that worked in the repository is a zombie (killed, not reaped yet)" do
    pid = start(script("reprepro", "exit 0"), chdir: repository)
    sleep(0.2) # exited; this process, its parent, has not waited for it
    expect(File.read("/proc/#{pid}/stat")).to match(/\) Z /)
    expect(described_class.clear(repository)).to eq(lock)
  end
end
