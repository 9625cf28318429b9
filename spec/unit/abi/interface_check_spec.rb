# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/abi/interface_check"
require "relspec/abi/verdict"

RSpec.describe Relspec::Abi::InterfaceCheck do
  def side(version, files, dumps = {}, root: nil)
    described_class::Side.new(version: version, files: files, dumps: dumps, root: root)
  end

  def entry(kind:, content:)
    Relspec::Abi::InstalledFiles::Entry.new(kind: kind, content: content)
  end

  def file(content)
    entry(kind: :file, content: content)
  end

  # abidiff stands in as a table: this spec is about the decision; the
  # corpus (spec/relspec/abi/early_cutoff_spec.rb) runs the real one.
  def check(verdicts = {})
    calls = []
    compare = lambda do |old, new, headers:|
      calls << [old, new]
      headers_seen << headers
      Relspec::Abi::Verdict.new(verdict: verdicts.fetch([old, new]), summary: ["summary of #{new}"], changes: [])
    end
    [described_class.new(compare: compare), calls]
  end

  def headers_seen
    @headers_seen ||= []
  end

  let(:header) { { "opt/r/include/a.h" => file("h1") } }

  it "keeps the interface when every file is identical and compares no dump for identical library bytes" do
    files = header.merge("opt/r/lib/liba.so.1" => entry(kind: :library, content: "l1"),
                         "opt/r/lib/liba.so" => entry(kind: :link, content: "liba.so.1"))
    checker, calls = check
    verdict = checker.decide("base/a", old: side("1-1", files), new: side("1-2", files))
    expect(verdict.unchanged?).to be(true)
    expect(verdict.evidence.map { |item| [item.path, item.check, item.outcome] }).to eq(
      [["opt/r/include/a.h", :bytes, :identical], ["opt/r/lib/liba.so", :link, :identical],
       ["opt/r/lib/liba.so.1", :abi, :identical]]
    )
    expect(calls).to eq([])
    expect([verdict.version, verdict.against]).to eq(%w[1-2 1-1])
  end

  it "asks abidiff about a library whose bytes moved: unchanged and compatible keep, changed and incompatible do not" do
    old_files = header.merge("opt/r/lib/liba.so.1" => entry(kind: :library, content: "l1"))
    new_files = header.merge("opt/r/lib/liba.so.1" => entry(kind: :library, content: "l2"))
    { "unchanged" => true, "compatible" => true, "changed" => false, "incompatible" => false }.each do |name, kept|
      checker, calls = check(%w[old.gz new.gz] => name)
      verdict = checker.decide("base/a", old: side("1-1", old_files, { "liba.so.1" => "old.gz" }),
                                         new: side("1-2", new_files, { "liba.so.1" => "new.gz" }))
      expect(verdict.unchanged?).to be(kept), name
      expect(calls).to eq([%w[old.gz new.gz]])
      expect(verdict.evidence.last.to_h).to eq(path: "opt/r/lib/liba.so.1", check: :abi, outcome: name.to_sym,
                                               detail: "summary of new.gz")
    end
  end

  it "hands abidiff both builds' unpacked files, so that a type no installed header defines is left out" do
    old_files = { "lib/liba.so.1" => entry(kind: :library, content: "l1") }
    new_files = { "lib/liba.so.1" => entry(kind: :library, content: "l2") }
    checker, = check(%w[old.gz new.gz] => "unchanged")
    checker.decide("base/a", old: side("1-1", old_files, { "liba.so.1" => "old.gz" }, root: "/tmp/old"),
                             new: side("1-2", new_files, { "liba.so.1" => "new.gz" }, root: "/tmp/new"))
    checker.decide("base/a", old: side("1-1", old_files, { "liba.so.1" => "old.gz" }),
                             new: side("1-2", new_files, { "liba.so.1" => "new.gz" }, root: "/tmp/new"))
    expect(headers_seen).to eq([%w[/tmp/old /tmp/new], nil])
  end

  it "changes the interface when a library has no dump to compare on either side" do
    old_files = { "lib/liba.so.1" => entry(kind: :library, content: "l1") }
    new_files = { "lib/liba.so.1" => entry(kind: :library, content: "l2") }
    checker, calls = check
    verdict = checker.decide("base/a", old: side("1-1", old_files), new: side("1-2", new_files, { "liba.so.1" => "n.gz" }))
    expect(verdict.changes.map(&:to_s)).to eq(["lib/liba.so.1: no dump (no ABI dump of the old build)"])
    expect(calls).to eq([])
  end

  it "changes the interface for a file that differs, is added or removed, a link that moved or a file that became a link" do
    old_files = { "h/a.h" => file("1"), "h/gone.h" => file("g"), "lib/liba.so" => entry(kind: :link, content: "liba.so.1"),
                  "share/x" => file("x") }
    new_files = { "h/a.h" => file("2"), "h/new.h" => file("n"), "lib/liba.so" => entry(kind: :link, content: "liba.so.2"),
                  "share/x" => entry(kind: :link, content: "y") }
    verdict = check.first.decide("base/a", old: side("1-1", old_files), new: side("1-2", new_files))
    expect(verdict.changes.map { |item| [item.path, item.outcome] }).to eq(
      [["h/a.h", :differs], ["h/gone.h", :removed], ["h/new.h", :added], ["lib/liba.so", :differs], ["share/x", :kind]]
    )
  end

  it "never keeps the dependents when a side installs nothing: nothing read is nothing proven" do
    verdict = check.first.decide("base/a", old: side("1-1", {}), new: side("1-2", {}))
    expect(verdict.unchanged?).to be(false)
    expect(verdict.changes.map(&:to_s)).to eq([": no files (the old and new build installs nothing)"])
  end
end
