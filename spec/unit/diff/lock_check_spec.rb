# frozen_string_literal: true

require "relspec/diff/lock_check"
require "relspec/project"

# What `relspec plan --check` says moved between the committed lock and the
# planned one: in memory (a lock is read here only through #to_h).
RSpec.describe Relspec::Diff::LockCheck do
  def lock(**changes)
    entry = { "decision" => "build", "deb" => "rock-r-a", "version" => "1-1~bookworm", "depends" => ["rock-r-b"] }
    Struct.new(:to_h).new({ "spec_digest" => "s", "ancestors" => {}, "packages" => { "a" => {} }, "history" => {},
                            "warnings" => [], "notes" => [], "targets" => { "bookworm/amd64" => { "a" => entry } } }.merge(changes))
  end

  it "names each section that moved" do
    reasons = described_class.reasons(lock, lock("spec_digest" => "t", "packages" => {}))
    expect(reasons).to eq([described_class::INPUTS.fetch("spec_digest"), described_class::INPUTS.fetch("packages")])
    expect(described_class.reasons(lock, lock)).to eq([])
  end

  it "blames depends: only when nothing else of the decisions differs" do
    without = lock("targets" => { "bookworm/amd64" => { "a" => { "decision" => "build", "deb" => "rock-r-a",
                                                                 "version" => "1-1~bookworm" } } })
    expect(described_class.reasons(without, lock)).to eq([described_class::DEPENDS])
    other = lock("targets" => { "bookworm/amd64" => { "a" => { "decision" => "inherit", "deb" => "rock-p-a" } } })
    expect(described_class.reasons(other, lock)).to eq([])
  end

  it "checks the specs named, or refuses a folder without specs/" do
    expect(described_class.spec_paths(["specs/a.yml"], Relspec::Project.new("/nowhere"))).to eq(["specs/a.yml"])
    expect { described_class.spec_paths([], Relspec::Project.new("/nowhere")) }
      .to raise_error(Relspec::Error, "no /nowhere/specs/ folder here: run from the project root or name the spec files")
  end
end
