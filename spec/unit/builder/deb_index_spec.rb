# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "relspec/builder/deb_index"
require "relspec/builder/build_dependency_set"

# A build's .debs as a flat archive (apt-ftparchive and apt-get run on it
# for real in spec/relspec/builder/sbuild_spec.rb's layered builds).
RSpec.describe Relspec::Builder::DebIndex do
  around do |example|
    Dir.mktmpdir("deb-index-unit") { |dir| @dir = dir and example.run }
  end

  def package(name, version, arch)
    Relspec::Builder::BuildDependencySet::Package.new(name: name, version: version, arch: arch)
  end

  it "links each .deb in once, names its archive and finds a package's file by name, version and architecture" do
    debs = %w[a b].map { |name| File.join(@dir, name) }
    debs.each { |dir| FileUtils.mkdir_p(dir) }
    first, again = debs.map { |dir| File.join(dir, "rel-one_1.0-1_amd64.deb").tap { |deb| File.write(deb, dir) } }
    scratch = File.join(@dir, "scratch")
    Dir.mkdir(scratch)
    index = described_class.new(scratch, [first, again])
    expect(Dir.children(index.dir)).to eq(["rel-one_1.0-1_amd64.deb"])
    expect(File.read(File.join(index.dir, "rel-one_1.0-1_amd64.deb"))).to eq(debs.first)
    expect(File.stat(index.dir).mode & 0o777).to eq(0o755)
    expect(File.read(index.sources)).to eq("deb [trusted=yes] file:#{index.dir} ./\n")

    File.write(File.join(index.dir, "Packages"),
               "Package: rel-one\nVersion: 2:1.0-1\nArchitecture: amd64\nFilename: ./rel-one_1.0-1_amd64.deb\n")
    expect(index.file(package("rel-one", "2:1.0-1", "amd64"))).to eq("rel-one_1.0-1_amd64.deb")
    expect(index.file(package("rel-one", "1.0-1", "amd64"))).to be_nil
    expect(index.file(package("rel-one", "2:1.0-1", "all"))).to be_nil
  end

  it "indexes and fetches the archive with this machine's apt-get, its state in the caller's folders" do
    index = described_class.new(@dir, [])
    lists = File.join(@dir, "lists")
    command = index.update_command("/run/lower", lists, @dir)
    expect(command.first(5)).to eq(["sh", "-c", 'cd "$1" && apt-ftparchive packages . > Packages && shift && exec "$@"',
                                    "sh", index.dir])
    expect(command.drop(5)).to eq(["apt-get", "-o", "Dir=/run/lower/", "-o", "Dir::Etc::sourcelist=#{index.sources}",
                                   "-o", "Dir::Etc::sourceparts=#{@dir}/no-parts", "-o", "Dir::State::Lists=#{lists}",
                                   "-o", "Dir::Cache=#{@dir}/cache", "-o", "Dir::Log=#{@dir}", "-o", "Debug::NoLocking=1",
                                   "update"])
    expect(File.directory?(File.join(lists, "partial"))).to be(true)
  end
end
