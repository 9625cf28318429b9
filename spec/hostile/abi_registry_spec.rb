# frozen_string_literal: true

require "spec_helper"
require_relative "../support/demo_child_dumps"
require "cgi"

# An ancestor's published type registry (oroGen's .tlb, compared by
# Abi::TypeRegistry) built to hurt (issue 46 case 6): a "billion laughs"
# DTD of entity definitions made `relspec abi`, `relspec report` and so
# `relspec publish` exit 70; a registry of a million types took 232 s and
# 3.4 GB. A registry is read with no DTD and with its size and number of
# types bounded (docs/limits.md): `relspec abi` refuses it in one line
# naming the dump (exit 1), and the status page says why its ABI verdicts
# were not computed.
RSpec.describe "relspec abi and report with a hostile type registry in an ancestor's dumps", :tmpdir do
  include DemoChildDumps

  let(:micro) { '<field name="microseconds" type="/int64_t" offset="0"></field>' }

  # Ten levels of ten: 10^10 "lol" from 700 bytes.
  let(:billion_laughs) do
    entities = (1..9).map { |level| %(<!ENTITY lol#{level} "#{"&lol#{level - 1};" * 10}">) }.join("\n")
    %(<?xml version="1.0"?>\n<!DOCTYPE typelib [\n<!ENTITY lol0 "lol">\n#{entities}\n]>\n) +
      %(<typelib>\n<compound name="&lol9;" size="8" source_id="">#{micro}</compound>\n</typelib>\n)
  end

  def abi(root)
    relspec("abi", "specs/demo-child.yml", "--out", "out", chdir: root, within: %w[timeout 60])
  end

  def page(root)
    run = relspec("report", "specs/demo-child.yml", "--out", "out", chdir: root, within: %w[timeout 60])
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    File.read(File.join(root, "out", "demo-child", "report", "index.html"))[/not computed: [^<]*/]
  end

  it "refuses a registry with entity definitions (a DTD), naming the dump" do
    demo_child_built(@dir, registry(8, micro))
    dump = demo_base_published(@dir, billion_laughs)
    run = abi(@dir)
    message = "#{dump} has a DTD (<!DOCTYPE>: entity definitions), which a typelib registry never has: refused, not compared"
    expect([run.exit_code, run.stdout, run.stderr]).to eq([1, "", "relspec: error: #{message}\n"])
    expect(page(@dir)).to eq("not computed: #{CGI.escapeHTML(message)}")
  end

  it "refuses an entity a registry refers to without a DTD" do
    demo_child_built(@dir, registry(8, micro))
    dump = demo_base_published(@dir, registry(8, micro).sub("/base/Time", "/base/&lol9;"))
    run = abi(@dir)
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: #{dump} refers to the entity \"&lol9;\", which no " \
                                                  "typelib registry defines: refused, not compared\n"])
  end

  # demo-child built, demo-base publishing a registry of /base/Time after
  # +count+ types made by the block (index → element); the published dump.
  def published_types(count, &type)
    demo_child_built(@dir, registry(8, micro))
    types = (1..count).map(&type).join
    demo_base_published(@dir, registry(8, micro).sub("<typelib>\n", "<typelib>\n#{types}"))
  end

  it "refuses a registry of a million types by its size, at once" do
    dump = published_types(1_000_000) { |index| %(<numeric name="/t#{index}" category="sint" size="8"></numeric>\n) }
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    run = abi(@dir)
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 15
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to match(/\Arelspec: error: #{Regexp.escape(dump)} is a type registry of \d+ bytes, more than 8388608: not compared\n\z/)
  end

  it "refuses a registry of more types than its bound, within its size" do
    dump = published_types(60_000) { |index| %(<null name="/t#{index}"/>\n) }
    run = abi(@dir)
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: #{dump} is a type registry of more than 50000 types: " \
                                                  "not compared (the rest was not read)\n"])
  end

  it "still compares a registry that names its types with the XML's own references" do
    demo_child_built(@dir, registry(16, "#{micro}<field name=\"flags\" type=\"/std/vector&lt;/int64_t&#x3e;\" offset=\"8\"></field>"))
    demo_base_published(@dir, registry(8, micro))
    run = abi(@dir)
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    expect(run.stdout).to include("field flags (/std/vector</int64_t>) added at offset 8")
  end
end
