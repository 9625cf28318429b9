# frozen_string_literal: true

require_relative "unit_helper"
require "stringio"
require "relspec/cache_writer"

# Entries written into a temporary folder: one that cannot be written
# (a directory in the way, a folder that is a file) is noted once for the
# whole writer, whichever entry it is, and the caller goes on.
RSpec.describe Relspec::CacheWriter, :tmpdir do
  let(:notes) { StringIO.new }
  let(:writer) { described_class.new(notes: notes) }

  it "writes an entry, its folders made, and says nothing" do
    path = File.join(@dir, "a", "b", "entry.yml")
    expect(writer.write(path, "bytes")).to be(true)
    expect(File.read(path)).to eq("bytes")
    expect(notes.string).to eq("")
  end

  it "notes the first entry that cannot be written, once for every entry after it" do
    FileUtils.mkdir_p(File.join(@dir, "entry", "in-the-way"))
    File.write(File.join(@dir, "file"), "")
    expect(writer.write(File.join(@dir, "entry"), "bytes")).to be(false)
    expect(writer.write(File.join(@dir, "file", "below"), "bytes")).to be(false)
    expect(notes.string).to eq("relspec: note: the cache entry #{@dir}/entry cannot be written (Is a directory); " \
                               "going on without it (only slower)\n")
  end

  it "notes a folder it cannot make with the system's reason" do
    File.write(File.join(@dir, "file"), "")
    expect(writer.write(File.join(@dir, "file", "below", "entry"), "bytes")).to be(false)
    expect(notes.string).to eq("relspec: note: the cache entry #{@dir}/file/below/entry cannot be written " \
                               "(File exists); going on without it (only slower)\n")
  end

  it "notes nowhere without notes" do
    FileUtils.mkdir_p(File.join(@dir, "entry", "in-the-way"))
    expect(described_class.new(notes: nil).write(File.join(@dir, "entry"), "bytes")).to be(false)
  end
end
