# frozen_string_literal: true

require_relative "../unit_helper"
require "tmpdir"
require "fileutils"
require "json"
require "digest"
require "relspec/diff/abi_section"
require "relspec/diff/json_renderer"

# Diff::AbiSection over a project folder with a spec and a build folder
# whose build-results.yml records two dumps and no ancestor publishes one
# (so no abidiff runs: every library is "new"); the diffs are stand-ins
# with only what AbiSection reads (release, changed?, each target's
# changes and whether the new side builds the package).
module AbiSectionDoubles
  Change = Struct.new(:package, :new)
  Decision = Struct.new(:built) do
    def built?
      built
    end
  end
  TargetChanges = Struct.new(:target, :changes)
  ReleaseChanges = Struct.new(:release, :changed, :targets) do
    def changed?
      changed
    end
  end
end

RSpec.describe Relspec::Diff::AbiSection do
  around do |example|
    Dir.mktmpdir("relspec-unit-abi-section") do |dir|
      @dir = dir
      example.run
    end
  end

  def built(dir, files)
    records = files.map do |source, (package, name)|
      FileUtils.mkdir_p(File.join(dir, "results", source))
      File.write(File.join(dir, "results", source, name), name)
      "  #{source}:\n    package: #{package}\n    version: 1.0-1~bookworm\n    status: built\n    files:\n      " \
        "- { name: results/#{source}/#{name}, sha256: #{Digest::SHA256.hexdigest(name)}, size: #{name.size} }\n"
    end
    File.write(File.join(dir, "build-results.yml"), "relspec_build_results: 1\nrelease: child\ntarget: bookworm/amd64\n" \
                                                    "backend: host\npackages:\n#{records.join}")
    entries = files.map do |source, (package, _)|
      Relspec::Builder::BuildPlan::Entry.new(package: package, source: source, version: "1.0-1~bookworm",
                                             dsc: "#{source}/#{source}_1.0-1~bookworm.dsc", build_depends: [])
    end
    Relspec::Builder::BuildPlan.write(dir, release: "child", target: "bookworm/amd64", entries: entries)
  end

  before do
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "child.yml"), "release: child\nworkspace: ../ws\ntargets: { bookworm: [amd64] }\n" \
                                                      "maintainer: Demo <demo@example.org>\n")
    built(File.join(@dir, "out", "child", "bookworm-amd64"),
          "rock-child-a" => ["a", "liba.so.abi.xml.gz"], "rock-child-b" => ["b", "libb.so.1.abi.xml.gz"])
  end

  let(:section) { described_class.new(root: @dir, out: File.join(@dir, "out")) }

  it "shows only the libraries of the changed packages the new side builds" do
    diff = AbiSectionDoubles::ReleaseChanges.new("child", true, [AbiSectionDoubles::TargetChanges.new("bookworm/amd64", [AbiSectionDoubles::Change.new("a", AbiSectionDoubles::Decision.new(true)),
                                                                                                                         AbiSectionDoubles::Change.new("b", AbiSectionDoubles::Decision.new(false))])])
    report = section.reports([diff]).fetch("child")
    expect(report.targets.first.entries.map { |entry| [entry.package, entry.library, entry.name] }).to eq([["a", "liba.so", "new"]])
    json = JSON.parse(Relspec::Diff::JsonRenderer.render([], abi: { "child" => report }))
    expect(json["abi"]).to eq("child" => { "bookworm/amd64" => [{ "package" => "a", "library" => "liba.so", "verdict" => "new",
                                                                  "against" => nil, "summary" => [], "changes" => [] }] })
  end

  it "leaves out unchanged releases, releases without a spec here and releases not built here" do
    unchanged = AbiSectionDoubles::ReleaseChanges.new("child", false, [])
    elsewhere = AbiSectionDoubles::ReleaseChanges.new("other", true, [])
    expect(section.reports([unchanged, elsewhere])).to eq({})
    expect(described_class.new(root: @dir, out: File.join(@dir, "none")).reports([AbiSectionDoubles::ReleaseChanges.new("child", true, [])])).to eq({})
    expect(JSON.parse(Relspec::Diff::JsonRenderer.render([], abi: {}))).not_to have_key("abi")
  end
end
