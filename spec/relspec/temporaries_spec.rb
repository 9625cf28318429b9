# frozen_string_literal: true

require "spec_helper"

# Which leftovers a sweep removes: those of processes that are gone, told by
# pid and start time; never another file, never a live process's work.
RSpec.describe Relspec::Temporaries, :tmpdir do
  # A pid no process has now: one that just ended.
  def dead_pid
    pid = Process.spawn("true")
    Process.wait(pid)
    pid
  end

  it "keeps a live process's temporaries and removes those of ended processes, old names included" do
    sleeper = Process.spawn("sleep", "30")
    start = described_class.start_time(sleeper)
    dead = dead_pid
    names = {
      ".a.relspec-#{sleeper}-#{start}-0badcafe" => :kept,                 # alive
      ".b.relspec-#{sleeper}-#{start + 1}-0badcafe.tar.zst" => :removed,  # the pid, another process
      ".c.relspec-#{dead}-#{start}-0badcafe" => :removed,
      ".d.relspec-#{dead}-0badcafe" => :removed,                          # an earlier version's name
      ".e.#{dead}.tmp" => :removed,
      ".f.relspec-#{sleeper}-0badcafe" => :kept,                          # pid only: alive
      "rock-x" => :kept,
      ".relspec-input" => :kept
    }
    names.each_key { |name| Dir.mkdir(File.join(@dir, name)) }
    removed = described_class.sweep(@dir)
    expect(removed.sort).to eq(names.select { |_, fate| fate == :removed }.keys.sort)
    expect(Dir.children(@dir).sort).to eq(names.select { |_, fate| fate == :kept }.keys.sort)
  ensure
    Process.kill("KILL", sleeper)
    Process.wait(sleeper)
  end

  it "names a temporary after this process, so its own sweep keeps it" do
    path = described_class.path(@dir, "x", suffix: ".tar.zst")
    File.write(path, "")
    expect(File.basename(path)).to match(/\A\.x\.relspec-#{Process.pid}-[1-9]\d*-[0-9a-f]{8}\.tar\.zst\z/)
    expect(described_class.sweep(@dir)).to eq([])
  end
end
