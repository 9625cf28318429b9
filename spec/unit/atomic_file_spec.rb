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

  it "copies a file only when the bytes differ, never reading through a link as the source" do
    Dir.mktmpdir do |dir|
      source = File.join(dir, "build.log")
      copy = File.join(dir, "copy.log")
      File.write(source, "error: x\n")
      expect(described_class.copy(copy, source)).to be(true)
      expect(described_class.copy(copy, source)).to be(false)
      expect(File.read(copy)).to eq("error: x\n")
      File.write(source, "error: y\n")
      expect(described_class.copy(copy, source)).to be(true)
      expect(File.read(copy)).to eq("error: y\n")
      File.symlink(source, File.join(dir, "link.log"))
      expect { described_class.copy(File.join(dir, "other.log"), File.join(dir, "link.log")) }
        .to raise_error(Relspec::Error, /cannot write .*other.log/)
      expect(Dir.children(dir).sort).to eq(%w[build.log copy.log link.log])
    end
  end
end
