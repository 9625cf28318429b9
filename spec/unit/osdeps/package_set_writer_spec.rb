# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/osdeps/package_set_writer"

# The package set's folder belongs to its maintainer (issue 33): only
# relspec's files change, each only when its bytes do.
RSpec.describe Relspec::Osdeps::PackageSetWriter do
  around { |example| Dir.mktmpdir { |dir| @dir = dir and example.run } }

  let(:files) { { "init.rb" => "# → non-ASCII\n", "data/a.yml" => "a\n", "lib/x.rb" => "x\n" } }

  it "writes every file the first time and none when the bytes are the same (non-ASCII text included)" do
    expect(described_class.write(@dir, files).written).to eq(files.keys)
    again = described_class.write(@dir, files)
    expect(again.changed?).to be(false)
    expect(File.binread(File.join(@dir, "init.rb"))).to eq("# → non-ASCII\n".b)
  end

  it "keeps .git and the maintainer's files, removes its own stale files in lib/ and data/ and their empty folders" do
    described_class.write(@dir, files.merge("data/old/b.yml" => "b\n"))
    FileUtils.mkdir_p(File.join(@dir, ".git"))
    File.write(File.join(@dir, ".git", "HEAD"), "ref\n")
    File.write(File.join(@dir, "README.md"), "mine\n")
    result = described_class.write(@dir, files)
    expect([result.written, result.removed]).to eq([[], ["data/old/b.yml"]])
    expect(Dir.glob("**/*", File::FNM_DOTMATCH, base: @dir).reject { |path| path.end_with?(".") }.sort)
      .to eq(%w[.git .git/HEAD README.md data data/a.yml init.rb lib lib/x.rb])
  end

  it "refuses a symbolic link where it writes, before writing anything" do
    Dir.mktmpdir do |elsewhere|
      File.symlink(elsewhere, File.join(@dir, "lib"))
      expect { described_class.write(@dir, files) }.to raise_error(Relspec::Error, /lib is a symbolic link/)
      expect(Dir.children(elsewhere)).to eq([])
      expect(File.exist?(File.join(@dir, "init.rb"))).to be(false)
    end
  end
end
