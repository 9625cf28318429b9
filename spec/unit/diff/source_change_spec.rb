# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/source_record"
require "relspec/diff/source_change"

RSpec.describe Relspec::Diff::SourceChange do
  def record(fields)
    Relspec::Plan::SourceRecord.from({ "url" => "https://example.org/t.git", "commit" => "1" * 40 }.merge(fields))
  end

  it "names every moved field of a package whose decisions did not change" do
    change = described_class.of("base/types", record({}), record("commit" => "2" * 40, "url" => "https://evil.example.org/t.git"),
                                decided: false)
    expect(change.to_s).to eq("base/types: source url https://example.org/t.git → https://evil.example.org/t.git, " \
                              "commit 111111111111 → 222222222222 (no decision changed)")
    expect(change.to_h).to eq("package" => "base/types", "decisions_changed" => false,
                              "fields" => { "url" => { "old" => "https://example.org/t.git", "new" => "https://evil.example.org/t.git" },
                                            "commit" => { "old" => "1" * 40, "new" => "2" * 40 } })
  end

  it "leaves to the decision changes what they show, but never another repository" do
    expect(described_class.of("base/types", record({}), record("commit" => "2" * 40), decided: true)).to be_nil
    change = described_class.of("base/types", record({}), record("commit" => "2" * 40, "url" => "u\e[2J"), decided: true)
    expect(change.to_s).to eq("base/types: source url https://example.org/t.git → u\\e[2J")
  end

  it "is nothing when the records are equal" do
    expect(described_class.of("base/types", record({}), record({}), decided: false)).to be_nil
  end
end
