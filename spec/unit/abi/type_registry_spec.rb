# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/abi/type_registry"

# Registries written the way typelib's tlb exporter writes them
# (tools/typelib lang/tlb/export.cc: one element per type with name, size
# and source_id, fields with name, type and offset, metadata inside).
RSpec.describe Relspec::Abi::TypeRegistry do
  def registry(types)
    xml = +"<?xml version=\"1.0\"?>\n<typelib>\n"
    types.each { |line| xml << "  #{line}\n" }
    xml << "</typelib>\n"
    described_class.parse(xml, file: "std.tlb")
  end

  let(:time) do
    '<compound name="/base/Time" size="8" source_id="/base/Time.hpp"><field name="microseconds" type="/int64_t" offset="0">' \
      '<metadata key="doc"><![CDATA[since the epoch]]></metadata></field><metadata key="source_file_line" /></compound>'
  end
  let(:numeric) { '<numeric name="/int64_t" category="sint" size="8" source_id="">    </numeric>' }

  it "is unchanged when every type keeps its layout (metadata does not count)" do
    other = time.sub("since the epoch", "microseconds since 1970")
    expect(registry([numeric, time]).compare(registry([time.sub(time, other), numeric])).verdict).to eq("unchanged")
  end

  it "names a field added to a type as a layout change: size, the new field, the fields it moved" do
    grown = '<compound name="/base/Time" size="16" source_id="/base/Time.hpp">' \
            '<field name="flags" type="/int32_t" offset="0"></field>' \
            '<field name="microseconds" type="/int64_t" offset="8"></field></compound>'
    verdict = registry([numeric, time]).compare(registry([numeric, grown]))
    expect(verdict.verdict).to eq("changed")
    expect(verdict.summary).to eq(["Types changes summary: 0 Removed, 1 Changed, 0 Added types"])
    expect(verdict.changes).to eq(["[C] /base/Time:", "  size 8 -> 16 bytes", "  field microseconds offset 0 -> 8",
                                   "  field flags (/int32_t) added at offset 0"])
  end

  it "is compatible when types are only added, incompatible when one is removed" do
    angle = '<compound name="/base/Angle" size="8" source_id=""><field name="rad" type="/double" offset="0"></field></compound>'
    expect(registry([time]).compare(registry([time, angle])).verdict).to eq("compatible")
    removed = registry([time, angle]).compare(registry([time]))
    expect([removed.verdict, removed.changes]).to eq(["incompatible", ["[D] /base/Angle"]])
  end

  it "sees a field's type change" do
    other = time.sub('type="/int64_t"', 'type="/uint64_t"')
    expect(registry([time]).compare(registry([other])).changes).to eq(["[C] /base/Time:", "  field microseconds type /int64_t -> /uint64_t"])
  end

  it "refuses what is not a registry, naming the file" do
    expect { described_class.parse("<html></html>", file: "x.tlb") }.to raise_error(Relspec::ToolError, /x.tlb is not a typelib registry/)
    expect { described_class.parse("<typelib><compound", file: "y.tlb") }.to raise_error(Relspec::ToolError, /y.tlb is not a typelib registry/)
  end

  it "resolves the XML's own entities and character references in names, as typelib writes them" do
    vector = '<container name="/std/vector&lt;/double&#62;" size="24" kind="/std/vector" of="/double"></container>'
    expect(registry([vector]).types.keys).to eq(["/std/vector</double>"])
  end

  it "refuses a DTD before anything it defines is expanded, and an entity no DTD defined" do
    laughs = %(<?xml version="1.0"?><!DOCTYPE typelib [<!ENTITY a "aaaaaaaaaa"><!ENTITY b "&a;&a;&a;&a;&a;">]>) +
             '<typelib><null name="&b;"/></typelib>'
    expect { described_class.parse(laughs, file: "l.tlb") }
      .to raise_error(Relspec::ToolError, "l.tlb has a DTD (<!DOCTYPE>: entity definitions), which a typelib registry " \
                                          "never has: refused, not compared")
    expect { described_class.parse('<typelib><null name="/&b;"/></typelib>', file: "r.tlb") }
      .to raise_error(Relspec::ToolError, 'r.tlb refers to the entity "&b;", which no typelib registry defines: refused, not compared')
  end

  it "bounds a registry's size before reading it, and its types while it reads" do
    stub_const("#{described_class}::MAX_BYTES", 118)
    stub_const("#{described_class}::MAX_TYPES", 2)
    expect { described_class.parse("<typelib>#{' ' * 100}</typelib>", file: "big.tlb") }
      .to raise_error(Relspec::ToolError, "big.tlb is a type registry of 119 bytes, more than 118: not compared")
    expect(registry(['<null name="/a"/>', '<null name="/b"/>']).types.size).to eq(2)
    expect { registry(['<null name="/a"/>', '<null name="/b"/>', '<null name="/c"/>']) }
      .to raise_error(Relspec::ToolError, "std.tlb is a type registry of more than 2 types: not compared (the rest was not read)")
  end

  it "reads a file's size before its bytes", :tmpdir do
    path = File.join(@dir, "big.tlb")
    File.write(path, "<typelib>#{' ' * (8 << 20)}</typelib>")
    expect(File).not_to receive(:read)
    expect { described_class.read(path, file: "big.tlb") }.to raise_error(Relspec::ToolError, "big.tlb is a type registry of 8388627 bytes, more than 8388608: not compared")
  end
end
