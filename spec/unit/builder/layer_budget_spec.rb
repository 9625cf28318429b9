# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/builder/layer_budget"

# The bound on a run's kept build-dependency layers: sizes, uses, free
# space and memory in, which layers to give up and whether to make one out.
RSpec.describe Relspec::Builder::LayerBudget do
  gib = 1024**3

  def layer(key, gib, used:, in_use: false)
    Relspec::Builder::LayerBudget::Layer.new(key: key, bytes: gib * (1024**3), used: used, in_use: in_use)
  end

  let(:budget) { described_class.new(budget: 4 * gib, floor: 6 * gib) }

  it "makes a layer without evicting anything when it fits" do
    decision = budget.decide([layer("a", 1, used: 1)], estimate: gib, free: 20 * gib, available: 20 * gib)
    expect([decision.make, decision.evict]).to eq([true, []])
    expect(decision).to be_frozen
  end

  it "evicts the least recently used layers no build uses until the budget holds" do
    layers = [layer("a", 1, used: 3), layer("b", 1, used: 1), layer("c", 1, used: 2), layer("d", 1, used: 4)]
    decision = budget.decide(layers, estimate: gib, free: 20 * gib, available: nil)
    expect([decision.make, decision.evict]).to eq([true, %w[b]])
    decision = budget.decide(layers, estimate: 2 * gib, free: 20 * gib, available: nil)
    expect(decision.evict).to eq(%w[b c])
  end

  it "never evicts a layer in use, however old" do
    layers = [layer("old", 2, used: 1, in_use: true), layer("new", 2, used: 9)]
    decision = budget.decide(layers, estimate: gib, free: 20 * gib, available: nil)
    expect([decision.make, decision.evict]).to eq([true, %w[new]])
  end

  it "makes no layer and evicts nothing when even that leaves no room" do
    layers = [layer("a", 2, used: 1, in_use: true), layer("b", 2, used: 2, in_use: true), layer("c", 1, used: 3)]
    decision = budget.decide(layers, estimate: gib, free: 20 * gib, available: nil)
    expect([decision.make, decision.evict]).to eq([false, []])
    expect(decision.reason).to eq("no room (the layers in use take 4.0 GB, a new one about 1.0 GB, of a budget of 4.0 GB; " \
                                  "20.0 GB free on their file system; 6.0 GB must stay free)")
  end

  it "keeps the floor free on the file system and in memory (tmpfs), evicting for either" do
    layers = [layer("a", 1, used: 1), layer("b", 1, used: 2)]
    # within the budget, but memory short by a layer
    decision = budget.decide(layers, estimate: gib, free: 20 * gib, available: (7 * gib) - 1)
    expect([decision.make, decision.evict]).to eq([true, %w[a]])
    decision = budget.decide(layers, estimate: gib, free: 5 * gib, available: nil)
    expect([decision.make, decision.evict]).to eq([true, %w[a b]])
    decision = budget.decide(layers, estimate: gib, free: 4 * gib, available: 30 * gib)
    expect([decision.make, decision.evict]).to eq([false, []])
    expect(decision.reason).to include("4.0 GB free on their file system; 30.0 GB of memory available")
    # unknown room is not checked
    expect(budget.decide(layers, estimate: gib, free: nil, available: nil).make).to be(true)
  end

  it "takes a quarter of the file system, at most 8 GB on tmpfs, unless overridden" do
    expect(described_class.bytes(100 * gib, tmpfs: false)).to eq(25 * gib)
    expect(described_class.bytes(100 * gib, tmpfs: true)).to eq(8 * gib)
    expect(described_class.bytes(12 * gib, tmpfs: true)).to eq(3 * gib)
    expect(described_class.bytes(nil, tmpfs: true)).to eq(8 * gib)
    expect(described_class.bytes(100 * gib, tmpfs: true, override: 1)).to eq(1)
    expect(described_class.parse("20G")).to eq(20 * gib)
    expect(described_class.parse("512m")).to eq(512 * (1024**2))
    expect(described_class.parse(" 1000 ")).to eq(1000)
  end

  it "refuses an override that is no size, saying which setting" do
    ["", "-1", "1.5G", "8 GB", "lots"].each do |text|
      expect { described_class.parse(text) }.to raise_error(Relspec::InvalidOption, /\ARELSPEC_LAYER_BUDGET=".*": not a size/)
    end
  end
end
