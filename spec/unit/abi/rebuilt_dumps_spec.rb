# frozen_string_literal: true

require_relative "../unit_helper"
require "digest"
require "relspec/target"
require "relspec/builder/build_results"
require "relspec/abi/rebuilt_dumps"

# A repository's abi/<target>/ folder in a temporary folder, its index
# unreadable: the dump files there are listed again only when a build
# record vouches for them (source, file name, SHA256), the others named.
RSpec.describe Relspec::Abi::RebuiltDumps, :tmpdir do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:dir) { File.join(@dir, "repo", "abi", "bookworm-amd64") }

  def dump(relative, content)
    path = File.join(dir, relative)
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, content)
    path
  end

  def record(source, package, files)
    produced = files.map do |name, content|
      Relspec::Builder::BuildResults::Produced.new(name: "results/#{source}/#{name}",
                                                   sha256: Digest::SHA256.hexdigest(content), size: content.bytesize)
    end
    Relspec::Builder::BuildResults::Record.new(source: source, package: package, version: "1.0-1~bookworm",
                                               status: "built", files: produced)
  end

  it "lists the dumps a record vouches for with its package and version, and leaves out the others" do
    kept = dump("rock-r-one/one.tlb.abi.xml.gz", "one")
    changed = dump("rock-r-two/libtwo.so.1.abi.xml.gz", "two, changed since")
    moved = dump("rock-r-other/one.tlb.abi.xml.gz", "one") # the right bytes under another source
    dump("rock-r-one/notes.txt", "not a dump")
    records = [record("rock-r-one", "test/one", "one.tlb.abi.xml.gz" => "one", "x_1.deb" => "deb"),
               record("rock-r-two", "test/two", "libtwo.so.1.abi.xml.gz" => "two")]

    rebuilt = described_class.of(File.join(@dir, "repo"), target, records, problem: "index.yml:1:1: broken")
    expect(rebuilt.dumps.entries.map(&:to_h)).to eq([{ package: "test/one", source: "rock-r-one", version: "1.0-1~bookworm",
                                                       library: "one.tlb", file: kept,
                                                       sha256: Digest::SHA256.hexdigest("one") }])
    expect(rebuilt.left_out).to eq([moved, changed])
    expect(rebuilt.problem).to eq("index.yml:1:1: broken")
    expect(rebuilt).to be_frozen
  end

  it "never lists a link, whatever it points to" do
    target_file = dump("elsewhere/one.tlb.abi.xml.gz", "one")
    FileUtils.mkdir_p(File.join(dir, "rock-r-one"))
    File.symlink(target_file, File.join(dir, "rock-r-one", "one.tlb.abi.xml.gz"))
    File.symlink(File.join(dir, "elsewhere"), File.join(dir, "rock-r-linked"))
    records = [record("rock-r-one", "test/one", "one.tlb.abi.xml.gz" => "one"),
               record("rock-r-linked", "test/l", "one.tlb.abi.xml.gz" => "one")]
    rebuilt = described_class.of(File.join(@dir, "repo"), target, records, problem: "p")
    expect(rebuilt.dumps.entries).to eq([])
    expect(rebuilt.left_out).to eq([target_file])
  end

  it "makes an empty list of a folder that does not exist" do
    rebuilt = described_class.of(File.join(@dir, "none"), target, [], problem: "p")
    expect([rebuilt.dumps.entries, rebuilt.left_out]).to eq([[], []])
  end
end
