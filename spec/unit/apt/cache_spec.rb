# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/apt/cache"

# The apt cache in a temporary folder: an entry that is not a regular file
# reads as missing (a FIFO without waiting on it), one that cannot be
# written is noted once and skipped.
RSpec.describe Relspec::Apt::Cache, :tmpdir do
  let(:notes) { StringIO.new }
  let(:cache) { described_class.new(@dir, writer: Relspec::CacheWriter.new(notes: notes)) }
  let(:sha) { "a" * 64 }

  it "reads back what it wrote, and nothing without a folder" do
    cache.write(sha, "bookworm/main/Packages.gz", "bytes")
    expect(cache.read(sha, "bookworm/main/Packages.gz")).to eq("bytes")
    expect(cache.read(sha, "other")).to be_nil
    expect(described_class.new(nil).read(sha, "bookworm/main/Packages.gz")).to be_nil
    expect(notes.string).to eq("")
  end

  it "reads a FIFO or a directory at an entry's path as missing, at once" do
    FileUtils.mkdir_p(File.join(@dir, sha, "folder"))
    File.mkfifo(File.join(@dir, sha, "fifo"))
    expect(cache.read(sha, "fifo")).to be_nil
    expect(cache.read(sha, "folder")).to be_nil
  end

  it "notes once that an entry cannot be written, and goes on" do
    FileUtils.mkdir_p(File.join(@dir, sha, "entry", "in-the-way"))
    cache.write(sha, "entry", "bytes")
    cache.write(sha, "entry", "bytes")
    expect(notes.string).to eq("relspec: note: the cache entry #{@dir}/#{sha}/entry cannot be written (Is a directory); " \
                               "going on without it (only slower)\n")
  end

  it "notes a full file system as it notes any other failed write" do
    # a full file system cannot be made here without mounting one: the
    # write fails as AtomicFile reports ENOSPC
    allow(Relspec::AtomicFile).to receive(:write).and_raise(Relspec::Error, "cannot write x: No space left on device")
    expect(cache.write(sha, "entry", "bytes")).to be_nil
    expect(notes.string).to include("cannot be written (No space left on device)")
  end
end
