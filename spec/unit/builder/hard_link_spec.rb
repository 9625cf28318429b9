# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/hard_link"

RSpec.describe Relspec::Builder::HardLink, :tmpdir do
  it "links a file, which stays when the first path is replaced" do
    File.write(File.join(@dir, "a"), "old")
    described_class.place(File.join(@dir, "a"), File.join(@dir, "b"))
    expect(File.stat(File.join(@dir, "b")).ino).to eq(File.stat(File.join(@dir, "a")).ino)
    File.delete(File.join(@dir, "a"))
    File.write(File.join(@dir, "a"), "new")
    expect(File.read(File.join(@dir, "b"))).to eq("old")
  end

  # /proc refuses links (another filesystem): the file is copied
  it "copies where the filesystem refuses a link" do
    described_class.place("/proc/self/stat", File.join(@dir, "copy"))
    expect(File.stat(File.join(@dir, "copy")).nlink).to eq(1)
    expect(File.file?(File.join(@dir, "copy"))).to be(true)
  end
end
