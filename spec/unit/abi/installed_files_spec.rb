# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/abi/installed_files"

RSpec.describe Relspec::Abi::InstalledFiles do
  # A .deb's data archive as dpkg-deb --fsys-tarfile prints it.
  def tar(&)
    io = StringIO.new("".b)
    Gem::Package::TarWriter.new(io, &)
    io.rewind
    io
  end

  it "lists files by path with their SHA256, links with their target and ELF lib*.so* as libraries" do
    io = tar do |writer|
      writer.mkdir("./opt/r/include", 0o755)
      writer.add_file_simple("./opt/r/include/a.h", 0o644, 4) { |file| file.write("int;") }
      writer.add_file_simple("./opt/r/lib/liba.so.1", 0o644, 8) { |file| file.write("\x7FELFabcd".b) }
      writer.add_symlink("./opt/r/lib/liba.so", "liba.so.1", 0o777)
      writer.add_file_simple("./opt/r/lib/libfake.so", 0o644, 6) { |file| file.write("INPUT(") } # a linker script
    end
    files = described_class.from_tar(io, source: "a.deb")
    expect(files.transform_values { |entry| [entry.kind, entry.content] }).to eq(
      "opt/r/include/a.h" => [:file, Digest::SHA256.hexdigest("int;")],
      "opt/r/lib/liba.so.1" => [:library, Digest::SHA256.hexdigest("\x7FELFabcd".b)],
      "opt/r/lib/liba.so" => [:link, "liba.so.1"],
      "opt/r/lib/libfake.so" => [:file, Digest::SHA256.hexdigest("INPUT(")]
    )
  end

  it "leaves out the Debian changelog, which moves with every version, and the debug files" do
    io = tar do |writer|
      writer.add_file_simple("./usr/share/doc/rock-r-a/changelog.Debian.gz", 0o644, 1) { |file| file.write("x") }
      writer.add_file_simple("./usr/share/doc/native/changelog.gz", 0o644, 1) { |file| file.write("x") }
      writer.add_file_simple("./usr/share/doc/rock-r-a/copyright", 0o644, 1) { |file| file.write("c") }
      writer.add_file_simple("./usr/lib/debug/.build-id/ab/cd.debug", 0o644, 1) { |file| file.write("d") }
    end
    expect(described_class.from_tar(io, source: "a.deb").keys).to eq(["usr/share/doc/rock-r-a/copyright"])
  end
end
