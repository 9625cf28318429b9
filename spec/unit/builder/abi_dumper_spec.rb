# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "zlib"
require "relspec/builder/abi_dumper"

RSpec.describe Relspec::Builder::AbiDumper, :tmpdir do
  def file(path, content)
    full = File.join(@dir, path)
    FileUtils.mkdir_p(File.dirname(full))
    File.binwrite(full, content)
    full
  end

  it "finds the shared libraries a package ships: ELF files named lib*.so*, no links, no debug files" do
    elf = "\x7FELF#{'x' * 20}".b
    library = file("opt/rock/r/lib/libbase-logging.so.1.2", elf)
    File.symlink(library, File.join(@dir, "opt/rock/r/lib/libbase-logging.so"))
    file("opt/rock/r/lib/libfake.so", "INPUT(-lbase-logging)\n") # a linker script
    file("opt/rock/r/lib/libbase-logging.a", elf)
    file("usr/lib/debug/.build-id/ab/libshadow.so", elf)
    file("opt/rock/r/lib/pkgconfig/libx.so.pc", elf)
    expect(described_class.new(nil).libraries(@dir)).to eq([library])
  end

  it "finds the oroGen type registries a typekit package ships under share/orogen" do
    registry = file("opt/rock/r/rock-r-base-orogen-std/share/orogen/std.tlb", "<typelib/>")
    file("opt/rock/r/rock-r-base-orogen-std/share/orogen/std.typelist", "x")
    file("opt/rock/r/rock-r-base-orogen-std/share/doc/other.tlb", "<typelib/>")
    expect(described_class.new(nil).registries(@dir)).to eq([registry])
  end

  it "leaves a library abidw cannot read without a dump, says so in the build log, and keeps the others" do
    root = File.join(@dir, "root")
    good = file("root/opt/rock/r/lib/libgood.so.1", "\x7FELF#{'x' * 20}".b)
    bad = file("root/opt/rock/r/lib/libbad.so.1", "\x7FELF#{'y' * 20}".b)
    log = file("build.log", "")
    run = lambda do |command, **|
      raise Relspec::BuildError, "r: abidw failed (exit status 1)" if command.last == bad

      File.write(command[command.index("--out-file") + 1], "<abi-corpus/>") if command.include?("--out-file")
    end
    dumper = described_class.new(run)
    dumps = %w[libbad.so.1 libgood.so.1].filter_map do |name|
      dumper.send(:library_dump, File.join(root, "opt/rock/r/lib", name), root, File.join(@dir, "out"), log)
    end
    expect(dumps.map(&:library)).to eq(["libgood.so.1"])
    expect(File.read(log)).to eq("relspec: no ABI dump of libbad.so.1: r: abidw failed (exit status 1)\n")
    expect(good).to end_with("libgood.so.1")
  end

  it "names the library of a dump file, and nothing else" do
    expect(described_class.library_of("results/s/libbase-logging.so.abi.xml.gz")).to eq("libbase-logging.so")
    expect(described_class.library_of("results/s/libx.so.1.2.abi.xml.gz")).to eq("libx.so.1.2")
    expect(described_class.library_of("results/s/x_1_amd64.deb")).to be_nil
    expect(described_class.library_of("results/s/notalib.abi.xml.gz")).to be_nil
    expect(described_class.library_of("results/s/std.tlb.abi.xml.gz")).to eq("std.tlb")
    expect([described_class.registry?("std.tlb"), described_class.registry?("libstd.so")]).to eq([true, false])
  end

  it "compresses without a name or a time, so the same dump gives the same bytes" do
    xml = file("a.xml", "<abi-corpus/>\n")
    described_class.compress(xml, File.join(@dir, "one.gz"))
    File.utime(Time.at(0), Time.at(12_345), xml)
    described_class.compress(xml, File.join(@dir, "two.gz"))
    expect(File.binread(File.join(@dir, "one.gz"))).to eq(File.binread(File.join(@dir, "two.gz")))
    expect(Zlib::GzipReader.open(File.join(@dir, "one.gz")) { |gzip| [gzip.mtime.to_i, gzip.orig_name, gzip.read] })
      .to eq([0, nil, "<abi-corpus/>\n"])
  end
end
