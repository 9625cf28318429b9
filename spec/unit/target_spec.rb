# frozen_string_literal: true

require "relspec/target"

# The one Target value and the one `--target` selection of plan, why, check,
# build and publish: in memory.
RSpec.describe Relspec::Target do
  let(:effective) { Struct.new(:targets).new({ "bookworm" => %w[arm64 amd64], "bionic" => ["amd64"] }) }
  let(:targets) { described_class.all(effective) }

  it "lists every target of a spec, sorted, frozen" do
    expect(targets.map(&:to_s)).to eq(%w[bionic/amd64 bookworm/amd64 bookworm/arm64])
    expect(targets).to all(be_frozen)
    expect(targets.first.dir_name).to eq("bionic-amd64")
  end

  it "parses codename/arch and refuses anything else" do
    expect(described_class.parse("bookworm/amd64")).to eq(described_class.new("bookworm", "amd64"))
    ["bookworm", "/amd64", "bookworm/", "", nil].each do |text|
      expect { described_class.parse(text) }.to raise_error(Relspec::InvalidOption, %r{codename/arch})
    end
  end

  describe ".select" do
    it "selects all targets when none is named" do
      expect(described_class.select(nil, targets, "demo")).to eq(targets)
      expect(described_class.select([], targets, "demo")).to eq(targets)
    end

    it "selects one named target, or several in the order asked, each once" do
      expect(described_class.select("bookworm/arm64", targets, "demo").map(&:to_s)).to eq(["bookworm/arm64"])
      expect(described_class.select(%w[bookworm/arm64 bionic/amd64 bookworm/arm64], targets, "demo").map(&:to_s))
        .to eq(%w[bookworm/arm64 bionic/amd64])
    end

    it "names the release's targets when asked for another" do
      expect { described_class.select("trixie/amd64", targets, "demo") }
        .to raise_error(Relspec::InvalidOption,
                        "trixie/amd64 is not a target of demo (bionic/amd64, bookworm/amd64, bookworm/arm64)")
    end
  end
end
