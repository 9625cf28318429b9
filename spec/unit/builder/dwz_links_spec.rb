# frozen_string_literal: true

require_relative "../unit_helper"
require "fileutils"
require "relspec/builder/dwz_links"

RSpec.describe Relspec::Builder::DwzLinks, :tmpdir do
  it "links each multifile below .dwz by its build id, once" do
    FileUtils.mkdir_p(File.join(@dir, "debug/.dwz/x86_64-linux-gnu"))
    multifile = File.join(@dir, "debug/.dwz/x86_64-linux-gnu/pkg.debug")
    FileUtils.cp("/bin/true", multifile)
    id = Relspec::ElfFile.build_id(File.binread(multifile))
    link = File.join(@dir, "debug/.build-id", id[0, 2], "#{id[2..]}.debug")
    expect(described_class.add(File.join(@dir, "debug"))).to eq([link])
    expect(File.readlink(link)).to eq(multifile)
    expect(described_class.add(File.join(@dir, "debug"))).to eq([])
  end

  it "leaves a folder without multifiles, links and files that are no ELF alone" do
    FileUtils.mkdir_p(File.join(@dir, "debug/.dwz"))
    File.write(File.join(@dir, "debug/.dwz/notes.txt"), "not an ELF file")
    File.symlink("/bin/true", File.join(@dir, "debug/.dwz/link"))
    expect(described_class.add(File.join(@dir, "debug"))).to eq([])
    expect(described_class.add(File.join(@dir, "nothing"))).to eq([])
  end
end
