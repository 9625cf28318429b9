# frozen_string_literal: true

require_relative "../unit_helper"
require "digest"
require "relspec/publish/upload"
require "relspec/builder/build_results"

# One built package as publish reads it, from files in a temporary target
# folder: a .dsc with its tarball (as compile writes them) and the .debs
# the build recorded, a -dbgsym one among them.
RSpec.describe Relspec::Publish::Upload, :tmpdir do
  let(:source) { "rock-demo-base-logging" }
  let(:deb) { "results/#{source}/#{source}_0.1-1_amd64.deb" }
  let(:dbgsym) { "results/#{source}/#{source}-dbgsym_0.1-1_amd64.deb" }

  def write(name, text)
    path = File.join(@dir, name)
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, text)
    path
  end

  def record(files)
    Relspec::Builder::BuildResults::Record.new(
      source: source, package: "base/logging", version: "0.1-1", status: "built",
      files: files.map { |name| Relspec::Builder::BuildResults::Produced.of(@dir, name) }
    )
  end

  def upload(files, debug_symbols: false)
    described_class.of(record(files), @dir, "/out/build-results.yml", debug_symbols: debug_symbols)
  end

  before do
    tarball = write("#{source}/#{source}_0.1-1.tar.xz", "tarball")
    write("#{source}/#{source}_0.1-1.dsc", "Source: #{source}\nChecksums-Sha256:\n " \
                                           "#{Digest::SHA256.file(tarball).hexdigest} 7 #{File.basename(tarball)}\n")
    write(deb, "deb")
    write(dbgsym, "debug symbols")
  end

  it "leaves the -dbgsym .deb out of the repository by default, from its items and the pool guard's too" do
    debs = upload([deb, dbgsym]).debs
    expect(debs).to eq([File.join(@dir, deb)])
    expect(upload([deb, dbgsym]).items.map(&:pool)).to eq(
      ["pool/main/r/#{source}/#{source}_0.1-1.dsc", "pool/main/r/#{source}/#{source}_0.1-1.tar.xz",
       "pool/main/r/#{source}/#{File.basename(deb)}"]
    )
  end

  it "includes it when the spec asks for debug symbols" do
    expect(upload([deb, dbgsym], debug_symbols: true).debs).to eq([File.join(@dir, dbgsym), File.join(@dir, deb)])
    expect(upload([deb, dbgsym], debug_symbols: true).items.map(&:pool)).to include("pool/main/r/#{source}/#{File.basename(dbgsym)}")
  end

  it "still checks the -dbgsym .deb it leaves out against its record" do
    recorded = record([deb, dbgsym])
    write(dbgsym, "changed since")
    expect { described_class.of(recorded, @dir, "/out/build-results.yml") }
      .to raise_error(Relspec::PublishError, /#{source} 0.1-1 .* cannot be published: .*-dbgsym_0.1-1_amd64.deb has changed since it was built/)
  end

  it "refuses a build whose only .deb holds debug symbols, naming it" do
    expect { upload([dbgsym]) }
      .to raise_error(Relspec::PublishError, /produced only debug-symbol packages \(#{source}-dbgsym_0.1-1_amd64.deb\)/)
    expect(upload([dbgsym], debug_symbols: true).debs).to eq([File.join(@dir, dbgsym)])
  end
end
