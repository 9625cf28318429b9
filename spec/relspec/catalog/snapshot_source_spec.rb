# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/snapshot_source"

RSpec.describe Relspec::Catalog::SnapshotSource do
  before(:all) do
    @base = Dir.mktmpdir("relspec-workspace")
    @builder = DemoWorkspace.build(@base)
    @catalog = load_catalog(@builder.root)
  end

  after(:all) { FileUtils.rm_rf(@base) }

  def snapshot_file(text)
    path = File.join(@base, "catalog-#{text.hash.abs}.yml")
    File.write(path, text)
    path
  end

  it "round-trips a catalog byte for byte" do
    text = described_class.dump(@catalog)
    loaded = described_class.load(snapshot_file(text))
    expect(loaded).to eq(@catalog)
    expect(described_class.dump(loaded)).to eq(text)
  end

  it "writes no host paths, so workspaces in different folders give the same bytes" do
    other_base = Dir.mktmpdir("relspec-other")
    other = load_catalog(DemoWorkspace.build(other_base).root)
    expect(described_class.dump(other)).to eq(described_class.dump(@catalog))
    expect(described_class.dump(@catalog)).not_to include(@base)
  ensure
    FileUtils.rm_rf(other_base)
  end

  it "is what `relspec catalog export` writes, the same bytes on every run" do
    outputs = Array.new(2) do |i|
      out = File.join(@base, "export-#{i}.yml")
      run = relspec("catalog", "export", @builder.root, "--targets", "bionic,buster", "--output", out)
      expect(run.exit_code).to eq(0), run.stderr
      File.read(out)
    end
    expect(outputs[0]).to eq(outputs[1])
    expect(outputs[0]).to eq(described_class.dump(@catalog))
  end

  it "refuses a file that is not a snapshot" do
    path = snapshot_file("packages: {}\n")
    expect { described_class.load(path) }.to raise_error(Relspec::InvalidInput, /is not a relspec catalog snapshot/)
  end

  it "refuses to serve distributions the snapshot was not exported for" do
    require "relspec/catalog/source"
    path = snapshot_file(described_class.dump(@catalog))
    expect { Relspec::Catalog::Source.load(path, distributions(%w[bionic focal])) }
      .to raise_error(Relspec::InvalidInput, /no OS dependencies for focal/)
  end

  # Each edit damages one field of a real export; the message must name the
  # field and its line, never a Ruby exception.
  {
    "a package that is a list" => [%r{^  base/types:\n}, "  base/types: []\n  x:\n", "packages.base/types must be a mapping"],
    "a dependency list that is text" => [/^    dependencies:\n(    - .*\n)+/, "    dependencies: base/cmake\n",
                                         "dependencies must be a list"],
    "an unknown vcs key" => [/^    vcs:\n/, "    vcs:\n      colour: red\n", "vcs.colour must be one of"],
    "a build type that is a mapping" => [/^    build_type: .*\n/, "    build_type: { a: 1 }\n", "build_type must be text"],
    "an environment setting of an unknown type" => [/(?=^    build_type: )/, "    environment: [{ type: unset, name: X, values: [] }]\n",
                                                    "environment.0 must be {type: set|add|add_path"],
    "oroGen arguments that are not words" => [/(?=^    build_type: )/, "    orogen_arguments: [--corba, [a]]\n",
                                              "orogen_arguments.1 must be text"]
  }.each do |what, (pattern, replacement, message)|
    it "refuses #{what} at its line" do
      text = described_class.dump(@catalog)
      damaged = text.sub(pattern, replacement)
      expect(damaged).not_to eq(text)
      line = damaged[0, damaged.index(replacement)].count("\n") + 1
      path = snapshot_file(damaged)
      error = begin
        described_class.load(path)
        nil
      rescue Relspec::InvalidInput => e
        e
      end
      expect(error&.message).to include(message)
      expect(error.diagnostics.map { |d| d.location.line }).to include(a_value_between(line - 1, line + 1))
    end
  end
end
