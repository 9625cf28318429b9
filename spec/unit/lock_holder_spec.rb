# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/lock_holder"
require "time"

# Issue 46, case 16: a refused or waiting publish names who holds the lock
# and since when. The flock is held by this process through a second open
# file (a child process is not allowed here; the CLI test has one).
RSpec.describe Relspec::LockHolder do
  around do |example|
    Dir.mktmpdir("lock-holder") do |dir|
      @path = File.join(dir, "lock")
      File.write(@path, "")
      example.run
    end
  end

  it "names the holder's program, pid and start time in UTC" do
    File.open(@path) do |held|
      held.flock(File::LOCK_EX)
      text = File.open(@path) { |file| described_class.of(file) }
      program = File.basename(File.binread("/proc/self/cmdline").split("\0").first)
      match = text.match(/\A(.+) \(pid (\d+), since (\d{4}-\d\d-\d\d \d\d:\d\d:\d\d) UTC\)\z/)
      expect(match && [match[1], match[2].to_i]).to eq([program, Process.pid])
      since = Time.strptime("#{match[3]} UTC", "%Y-%m-%d %H:%M:%S %Z")
      expect(since).to be_between(Time.now - (24 * 3600), Time.now + 1)
    end
  end

  it "says 'another process' when nobody holds a lock on the file" do
    expect(File.open(@path) { |file| described_class.of(file) }).to eq("another process")
  end
end
