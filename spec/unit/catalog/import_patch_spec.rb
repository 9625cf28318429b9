# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/catalog/import_patch"

RSpec.describe Relspec::Catalog::ImportPatch do
  it "reads autobuild's patch list (path, level, text) with the paths the catalog writes" do
    importer = Struct.new(:patches).new([["/ws/set/a.patch", 0, "A"], ["/ws/set/b.patch", "2", "B"]])
    list = described_class.list_of(importer) { |path| path.delete_prefix("/ws/") }
    expect(list).to eq([{ "path" => "set/a.patch", "level" => 0, "content" => "A" },
                        { "path" => "set/b.patch", "level" => 2, "content" => "B" }])
    expect(list.map { |hash| described_class.from_h(hash).to_h }).to eq(list)
  end

  it "has no patches for an importer without a patch list (a package without importer)" do
    expect(described_class.list_of(nil) { |path| path }).to eq([])
  end
end
