# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "digest"
require "relspec/target"
require "relspec/builder/build_results"
require "relspec/abi/published_dumps"

RSpec.describe Relspec::Abi::PublishedDumps do
  let(:target) { Relspec::Target.new("bookworm", "amd64") }

  around do |example|
    Dir.mktmpdir("relspec-unit-abi") do |dir|
      @dir = dir
      example.run
    end
  end

  def record(source, package, files)
    produced = files.map do |name, content|
      path = File.join(@dir, "out", name)
      FileUtils.mkdir_p(File.dirname(path))
      File.write(path, content)
      Relspec::Builder::BuildResults::Produced.of(File.join(@dir, "out"), name)
    end
    Relspec::Builder::BuildResults::Record.new(source: source, package: package, version: "1.0-1~bookworm",
                                               status: "built", files: produced)
  end

  def index_path
    File.join(@dir, "repo", "abi", "bookworm-amd64", "index.yml")
  end

  it "copies the dumps of the built packages and lists them, the same bytes on every run" do
    records = [record("rock-r-base-logging", "base/logging",
                      "results/rock-r-base-logging/x_1.deb" => "deb",
                      "results/rock-r-base-logging/libbase-logging.so.abi.xml.gz" => "dump")]
    expect(described_class.write(File.join(@dir, "repo"), target, File.join(@dir, "out"), records)).to be(true)
    first = File.read(index_path)
    expect(described_class.write(File.join(@dir, "repo"), target, File.join(@dir, "out"), records)).to be(false)
    expect(File.read(index_path)).to eq(first)

    read = described_class.read(File.join(@dir, "repo"), target)
    expect(read.entries.map { |entry| [entry.package, entry.library, entry.version] })
      .to eq([["base/logging", "libbase-logging.so", "1.0-1~bookworm"]])
    expect(File.read(read.of("base/logging").first.file)).to eq("dump")
    expect(read.entries.first.sha256).to eq(Digest::SHA256.hexdigest("dump"))
  end

  it "keeps the dumps of packages not published this time, and replaces those that are" do
    repo = File.join(@dir, "repo")
    out = File.join(@dir, "out")
    described_class.write(repo, target, out, [record("rock-r-a", "a", "results/rock-r-a/liba.so.abi.xml.gz" => "a1"),
                                              record("rock-r-b", "b", "results/rock-r-b/libb.so.1.abi.xml.gz" => "b1")])
    described_class.write(repo, target, out, [record("rock-r-a", "a", "results/rock-r-a/liba2.so.abi.xml.gz" => "a2")])
    expect(described_class.read(repo, target).entries.map(&:library)).to eq(%w[liba2.so libb.so.1])
  end

  it "keeps the dumps of +current+ (an index made again), not of the index on disk" do
    repo = File.join(@dir, "repo")
    out = File.join(@dir, "out")
    FileUtils.mkdir_p(File.dirname(index_path))
    File.write(index_path, "damaged: [\n")
    kept = described_class::Entry.new(package: "b", source: "rock-r-b", version: "1", library: "libb.so.1",
                                      file: File.join(File.dirname(index_path), "rock-r-b", "libb.so.1.abi.xml.gz"),
                                      sha256: "b" * 64)
    current = described_class.new(File.dirname(index_path), [kept])
    described_class.write(repo, target, out, [record("rock-r-a", "a", "results/rock-r-a/liba.so.abi.xml.gz" => "a1")],
                          current: current)
    expect(described_class.read(repo, target).entries.map { |entry| [entry.library, entry.file] })
      .to eq([["liba.so", File.join(File.dirname(index_path), "rock-r-a/liba.so.abi.xml.gz")],
              ["libb.so.1", File.join(File.dirname(index_path), "rock-r-b/libb.so.1.abi.xml.gz")]])
  end

  it "writes nothing for packages without dumps" do
    records = [record("rock-r-data", "data", "results/rock-r-data/x_1_all.deb" => "deb")]
    expect(described_class.write(File.join(@dir, "repo"), target, File.join(@dir, "out"), records)).to be(false)
    expect(File.exist?(File.join(@dir, "repo", "abi"))).to be(false)
  end

  it "refuses to write through a source's folder, the target's folder or abi/ that is a link, and writes nothing" do
    repo = File.join(@dir, "repo")
    outside = File.join(@dir, "outside")
    FileUtils.mkdir_p(outside)
    File.write(File.join(outside, "liba.so.abi.xml.gz"), "mine")
    records = [record("rock-r-a", "a", "results/rock-r-a/liba.so.abi.xml.gz" => "a1")]
    ["abi", "abi/bookworm-amd64", "abi/bookworm-amd64/rock-r-a"].each do |link|
      FileUtils.rm_rf(File.join(repo, "abi"))
      FileUtils.mkdir_p(File.dirname(File.join(repo, link)))
      File.symlink(outside, File.join(repo, link))
      expect { described_class.write(repo, target, File.join(@dir, "out"), records) }
        .to raise_error(Relspec::PublishError, "#{repo}/#{link} is a symbolic link (to #{outside}): publish writes the " \
                                               "ABI dumps only inside #{repo}/abi/bookworm-amd64 and never through a " \
                                               "link; remove the link and publish again")
      expect(Dir.children(outside)).to eq(["liba.so.abi.xml.gz"])
      expect(File.read(File.join(outside, "liba.so.abi.xml.gz"))).to eq("mine")
    end
  end

  it "is empty for a repository without dumps" do
    expect(described_class.read(File.join(@dir, "none"), target).entries).to eq([])
  end

  {
    "a path leaving the folder" => ["file: ../../etc/libx.so.abi.xml.gz", "is not a plain path"],
    "a library name that is not one" => ["library: ../libx.so", "is not a shared library or type registry name"],
    "a file that is another library's dump" => ["file: s/liby.so.abi.xml.gz", "is not a dump of libx.so"],
    "a bad sha256" => ["sha256: abc", "sha256 must be 64 lowercase hex digits"],
    "an unknown key" => ["extra: 1", "unknown key \"extra\""]
  }.each do |what, (line, message)|
    it "refuses #{what} with the file and line" do
      fields = { "package" => "package: x", "source" => "source: s", "version" => "version: '1'",
                 "library" => "library: libx.so", "file" => "file: s/libx.so.abi.xml.gz", "sha256" => "sha256: #{'a' * 64}" }
      key = line[/\A\w+/]
      fields[key] = line
      FileUtils.mkdir_p(File.dirname(index_path))
      File.write(index_path, "relspec_abi_dumps: 1\ndumps:\n  - #{fields.values.join("\n    ")}\n")
      expect { described_class.read(File.join(@dir, "repo"), target) }.to raise_error(Relspec::InvalidInput) { |error|
        expect(error.diagnostics.first.message).to include(message)
        expect(error.diagnostics.first.location.line).to be >= 3
      }
    end
  end

  it "refuses an index of another format" do
    FileUtils.mkdir_p(File.dirname(index_path))
    File.write(index_path, "relspec_abi_dumps: 2\ndumps: []\n")
    expect { described_class.read(File.join(@dir, "repo"), target) }.to raise_error(Relspec::InvalidInput, /unknown format 2/)
  end
end
