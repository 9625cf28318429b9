# frozen_string_literal: true

require_relative "../unit_helper"
require "stringio"
require "relspec/catalog"
require "relspec/catalog/cache"

# The catalog cache over an empty workspace folder (no package, so its
# fingerprint reads no checkout): a catalog stored is read back without
# loading again, and a cache folder that cannot be written costs the
# loading only, with the run's one note.
RSpec.describe Relspec::Catalog::Cache, :tmpdir do
  let(:notes) { StringIO.new }
  let(:catalog) { Relspec::Catalog.new(packages: {}, codenames: ["bookworm"]) }
  let(:root) { File.join(@dir, "ws").tap { |dir| FileUtils.mkdir_p(dir) } }

  def fetch(cache)
    loads = 0
    result = cache.fetch(root, {}) do
      loads += 1
      catalog
    end
    [result, loads]
  end

  it "keeps a catalog and gives it back without loading it again" do
    cache = described_class.new(File.join(@dir, "cache"), writer: Relspec::CacheWriter.new(notes: notes))
    expect(fetch(cache)).to eq([catalog, 1])
    expect(fetch(cache)).to eq([catalog, 0])
    expect(notes.string).to eq("")
  end

  it "loads every time, with one note, when its folder cannot be written" do
    File.write(File.join(@dir, "cache"), "a file where the folder should be")
    cache = described_class.new(File.join(@dir, "cache"), writer: Relspec::CacheWriter.new(notes: notes))
    expect(fetch(cache)).to eq([catalog, 1])
    expect(fetch(cache)).to eq([catalog, 1])
    expect(notes.string.lines.size).to eq(1)
    expect(notes.string).to match(%r{\Arelspec: note: the cache entry #{@dir}/cache/\h{64}\.yml cannot be written})
  end
end
