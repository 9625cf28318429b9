# frozen_string_literal: true

require_relative "../unit_helper"
require "fileutils"
require "relspec/builder/interface_verdicts"

# Which builds are compared with the one they replace; the comparison
# itself runs dpkg-deb and abidiff (spec/relspec/builder/early_cutoff_build_spec.rb).
RSpec.describe Relspec::Builder::InterfaceVerdicts, :tmpdir do
  let(:results) { Relspec::Builder::BuildResults }

  def record(version, status: "built", files: nil)
    files ||= begin
      FileUtils.mkdir_p(File.join(@dir, "results/a"))
      File.write(File.join(@dir, "results/a/a_#{version}_amd64.deb"), "deb #{version}")
      [results::Produced.of(@dir, "results/a/a_#{version}_amd64.deb")]
    end
    results::Record.new(source: "a", package: "base/a", version: version, status: status, files: files)
  end

  let(:entry) { Struct.new(:source, :package, :version).new("a", "base/a", "1-2") }

  it "compares only a build of another version whose files are all there with the bytes recorded" do
    verdicts = described_class.new({}, @dir)
    expect(verdicts.comparable?(nil, entry)).to be(false) # a first build
    expect(verdicts.comparable?(record("1-2"), entry)).to be(false) # the same version, built again
    expect(verdicts.comparable?(record("1-1", status: "failed", files: []), entry)).to be(false)
    previous = record("1-1")
    expect(verdicts.comparable?(previous, entry)).to be(true)
    File.write(File.join(@dir, "results/a/a_1-1_amd64.deb"), "damaged")
    expect(verdicts.comparable?(previous, entry)).to be(false)
  end

  it "decides nothing, and keeps nothing, when there is nothing to compare" do
    verdicts = described_class.of(Struct.new(:records) { def [](source) = records[source] }.new({}), [entry], @dir)
    expect(verdicts.decide(entry, [])).to be_nil
    expect(verdicts["a"]).to be_nil
  end
end
