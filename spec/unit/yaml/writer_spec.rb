# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/yaml/writer"
require "yaml"

RSpec.describe Relspec::Yaml::Writer do
  def round_trip(data)
    YAML.safe_load(described_class.dump(data))
  end

  it "writes nested data that YAML reads back unchanged" do
    data = {
      "plain" => "base/types", "numbers look" => ["1.0", "10", "0x1f", "1e3"], "words look" => %w[true no null ~ yes],
      "dates look" => ["2020-06-01", "2020-06-01T10:00:00Z"], "special" => ["a: b", "#x", "-x", "*x", "&x", "", " x", "x:", "a:b", "https://x.org/a", "1,2", "ubuntu,debian"],
      "text" => "two\nlines \"quoted\" é", "scalars" => [1, true, false, nil],
      "empty" => [{}, []], "nested" => { "list" => [{ "a" => ["b"] }, [["c"]]], "map" => { "k" => {} } }
    }
    expect(round_trip(data)).to eq(data)
  end

  it "writes plain scalars unquoted and the rest quoted" do
    expect(described_class.dump("a" => ["base/types", "1.0", "$AUTOPROJ_ROOT/x"]))
      .to eq(%(---\na:\n- base/types\n- "1.0"\n- $AUTOPROJ_ROOT/x\n))
  end

  it "writes osdeps keys as the published files do" do
    expect(described_class.dump("ubuntu,debian" => { "18.04,bionic,beaver,default" => "rock-x" }))
      .to eq("---\nubuntu,debian:\n  18.04,bionic,beaver,default: rock-x\n")
  end

  it "handles top-level scalars and empty collections" do
    expect([round_trip("x"), round_trip([]), round_trip({}), round_trip(nil)]).to eq(["x", [], {}, nil])
  end

  it "refuses values YAML would need tags for" do
    expect { described_class.dump("a" => :symbol) }.to raise_error(ArgumentError)
  end
end
