# frozen_string_literal: true

require_relative "unit_helper"
require "tmpdir"
require "relspec/atomic_file"

RSpec.describe Relspec::AtomicFile do
  it "leaves a file whose bytes equal the content alone, non-ASCII UTF-8 text included" do
    Dir.mktmpdir do |dir|
      path = File.join(dir, "a.rb")
      expect(described_class.update(path, "# → é\n")).to be(true)
      expect(described_class.update(path, "# → é\n")).to be(false)
      expect(described_class.update(path, "# → e\n")).to be(true)
      expect(File.binread(path)).to eq("# → e\n".b)
    end
  end
end
