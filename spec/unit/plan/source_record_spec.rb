# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/plan/source_record"

RSpec.describe Relspec::Plan::SourceRecord do
  let(:record) { described_class.from("url" => +"https://example.org/t.git", "commit" => "1" * 40, "branch" => "master") }

  it "is a frozen value read from the lock's mapping, written back in the lock's order" do
    expect(record).to be_frozen
    expect(record.url).to be_frozen
    expect(record["url"]).to eq("https://example.org/t.git")
    expect(record.to_h).to eq("url" => "https://example.org/t.git", "commit" => "1" * 40, "branch" => "master")
    expect(record.to_h.keys).to eq(%w[url commit branch])
    expect(described_class.fields).to eq(%w[url commit sha256 commit_time version tag branch])
    expect(described_class.from(record)).to equal(record)
  end

  it "names every field that differs" do
    other = described_class.from("url" => "https://evil.example.org/t.git", "commit" => "1" * 40, "tag" => "v1")
    expect(record.changes(other)).to eq("url" => ["https://example.org/t.git", "https://evil.example.org/t.git"],
                                        "tag" => [nil, "v1"], "branch" => ["master", nil])
    expect(record.changes(record)).to eq({})
  end

  it "refuses a field it does not define" do
    expect { described_class.from("colour" => "red") }.to raise_error(ArgumentError)
  end
end
