# frozen_string_literal: true

require_relative "unit_helper"
require "relspec/elf_file"

RSpec.describe Relspec::ElfFile do
  let(:elf) { File.binread("/bin/true") }

  it "reads a build id only from a well-formed ELF note and never beyond the bytes" do
    expect(described_class.build_id(elf)).to match(/\A\h{40}\z/)
    expect(described_class.build_id("junk")).to be_nil
    expect(described_class.build_id(elf.byteslice(0, 200))).to be_nil
    expect(described_class.build_id(described_class::MAGIC + ("\xFF".b * 100))).to be_nil
    expect(described_class.sections(elf.byteslice(0, 200))).to eq([])
  end

  it "names the sections" do
    expect(described_class.sections(elf).map(&:name)).to include(".text", ".note.gnu.build-id", ".gnu_debuglink")
  end

  it "zeroes the debug links and the build id, and nothing else, so builds of the same code compare equal" do
    other = elf.b
    id = described_class.sections(elf).find { |section| section.name == ".note.gnu.build-id" }
    other[id.offset + id.size - 1] = (other.getbyte(id.offset + id.size - 1) ^ 0xFF).chr
    expect(other).not_to eq(elf)
    expect(described_class.without_debug_links(other)).to eq(described_class.without_debug_links(elf))
    expect(described_class.without_debug_links(elf).bytesize).to eq(elf.bytesize)

    text = described_class.sections(elf).find { |section| section.name == ".text" }
    code = elf.b
    code[text.offset] = (code.getbyte(text.offset) ^ 0xFF).chr
    expect(described_class.without_debug_links(code)).not_to eq(described_class.without_debug_links(elf))
    expect(described_class.without_debug_links("not elf")).to eq("not elf")
  end
end
