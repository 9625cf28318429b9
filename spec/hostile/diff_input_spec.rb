# frozen_string_literal: true

require "spec_helper"
require_relative "../support/committed_releases"

# Whatever is given to `relspec diff` as OLD (issue 24, item 2): a binary
# file, an empty one, another format, a lock cut short or from a future
# format is one error naming the file, exit 1, never exit 70 and never a
# diff of a guess. NEW is the demo's real lock.
RSpec.describe "relspec diff on hostile inputs", :tmpdir do
  let(:good) { CommittedReleases.copy("demo-base/lock.yml", File.join(@dir, "good.yml")) }

  def diff(name, bytes)
    File.binwrite(File.join(@dir, name), bytes)
    run = relspec("diff", name, good, chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""]), run.stderr
    run.stderr
  end

  it "refuses a binary file at the first byte that is not text" do
    expect(diff("old.yml", "\x00\xFF\xFE\x01".b)).to start_with("old.yml:1:2: error[encoding]: invalid UTF-8 (bytes FF)\n")
  end

  it "refuses a gzip-compressed lock as not text" do
    expect(diff("old.yml", "\x1F\x8B\x08\x00".b)).to start_with("old.yml:1:2: error[encoding]: invalid UTF-8 (bytes 8B)\n")
  end

  it "refuses an empty file" do
    expect(diff("old.yml", "")).to eq("relspec: error: old.yml is empty: neither a relspec lock nor a release spec\n")
  end

  it "refuses JSON and plain text as neither lock nor spec" do
    expect(diff("old.json", "[1, 2]")).to eq("relspec: error: old.json is neither a relspec lock nor a release spec\n")
    expect(diff("old.txt", "hello\n")).to eq("relspec: error: old.txt is neither a relspec lock nor a release spec\n")
  end

  it "refuses a lock of a future format, naming its line" do
    expect(diff("old.yml", "---\nrelspec_lock: 9\nrelease: demo-base\n"))
      .to start_with("old.yml:2:15: error[lock]: cannot read the lock: unknown lock format 9 (this relspec reads 1 and 2)\n")
  end

  it "refuses a lock cut short instead of showing every package as added" do
    expect(diff("old.yml", File.read(good)[0, 300]))
      .to start_with("old.yml:2:1: error[lock]: cannot read the lock: the lock has no targets: section (cut short?)\n")
  end

  it "refuses a release folder whose lock.yml is a FIFO" do
    FileUtils.mkdir_p(File.join(@dir, "rel"))
    File.mkfifo(File.join(@dir, "rel", "lock.yml"))
    run = relspec("diff", "rel", good, chdir: @dir)
    expect([run.exit_code, run.stderr.lines.first]).to eq([1, "rel/lock.yml: error[unreadable-file]: not a regular file (fifo)\n"])
  end
end
