# frozen_string_literal: true

require_relative "../unit_helper"

RSpec.describe Relspec::Yaml::LocatedDocument do
  def parse(text)
    described_class.parse(text, file: "specs/x.yml")
  end

  it "keeps 1-based positions of keys and values" do
    document = parse("release: x\ntargets:\n  bionic: [amd64, arm64]\n")
    expect(document.location(["targets", "bionic", 1]).to_s).to eq("specs/x.yml:3:19")
    expect(document.key_location(%w[targets bionic]).to_s).to eq("specs/x.yml:3:3")
    expect(document.location(["release"]).to_s).to eq("specs/x.yml:1:10")
  end

  it "falls back to the enclosing value for paths that do not exist" do
    document = parse("repository:\n  url: x\n")
    expect(document.location(%w[repository path]).to_s).to eq("specs/x.yml:2:3")
  end

  it "reports duplicate keys at the second occurrence, naming the first" do
    document = parse("a: 1\nb: 2\na: 3\n")
    expect(document.diagnostics.map(&:to_s))
      .to eq(["specs/x.yml:3:1: error[duplicate-key]: duplicate key \"a\"\n  hint: it is already set at line 1; keep only one"])
    expect(document.data).to eq("a" => 1, "b" => 2)
  end

  it "keeps the text of scalars as written" do
    document = parse("v: 20.10\nq: '4.8'\n")
    expect(document.data).to eq("v" => 20.1, "q" => "4.8")
    expect(document.raw(["v"])).to eq("20.10")
  end

  it "keeps dates and symbols as text" do
    expect(parse("d: 2020-06-01\ns: :sym\n").data).to eq("d" => "2020-06-01", "s" => ":sym")
  end

  it "resolves aliases to their anchor's value" do
    expect(parse("a: &t [amd64]\nb: *t\n").data).to eq("a" => ["amd64"], "b" => ["amd64"])
  end

  it "turns a syntax error into one diagnostic with position" do
    document = parse("a: [1\nb: 2\n")
    expect(document).not_to be_ok
    expect(document.diagnostics.map(&:rule)).to eq(["yaml-syntax"])
    expect(document.diagnostics.first.location.line).to eq(1)
  end

  it "refuses Ruby object tags" do
    document = parse("a: !ruby/object:Object {}\n")
    expect(document.diagnostics.map(&:rule)).to eq(["yaml-tag"])
  end

  it "reports an unreadable file without raising" do
    document = described_class.load("/nonexistent/specs/x.yml")
    expect(document.diagnostics.map(&:rule)).to eq(["unreadable-file"])
  end

  it "says which keys were written plain as something other than text" do
    document = described_class.parse("a:\n  7: x\n  \"8\": y\n  true: z\n  name: w\n", file: "f.yml")
    expect(document.data["a"].keys).to eq(%w[7 8 true name])
    expect([%w[a 7], %w[a 8], %w[a true], %w[a name]].map { |path| document.typed_key?(path) }).to eq([true, false, true, false])
    expect(document.key_location(%w[a 7]).line).to eq(2)
  end
end
