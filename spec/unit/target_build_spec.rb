# frozen_string_literal: true

require_relative "unit_helper"
require "fileutils"
require "relspec/target_build"
require "relspec/target"

RSpec.describe Relspec::TargetBuild do
  around do |example|
    Dir.mktmpdir("relspec-unit-target-build") do |dir|
      @tree = Relspec::OutputTree.new(dir, "solo")
      example.run
    end
  end

  let(:target) { Relspec::Target.new("bookworm", "amd64") }
  let(:dir) { @tree.target_dir(target) }

  def plan(versions)
    entries = versions.map do |source, version|
      Relspec::Builder::BuildPlan::Entry.new(package: source.delete_prefix("rock-"), source: source, version: version,
                                             dsc: "#{source}/#{source}_#{version}.dsc", build_depends: [])
    end
    FileUtils.mkdir_p(dir)
    Relspec::Builder::BuildPlan.write(dir, release: "solo", target: target, entries: entries)
  end

  def results(versions)
    records = versions.map do |source, version|
      "  #{source}: { package: #{source.delete_prefix('rock-')}, version: #{version}, status: failed, reason: x }\n"
    end
    File.write(@tree.results_file(target), "relspec_build_results: 1\nrelease: solo\ntarget: bookworm/amd64\n" \
                                           "backend: host\npackages:\n#{records.join}")
  end

  it "is neither planned nor built before compile" do
    build = described_class.read(@tree, target)
    expect([build.plan, build.results, build.built?]).to eq([nil, nil, false])
    expect(build.dir).to eq(dir)
  end

  it "has a plan and no results before build" do
    plan("rock-a" => "1.0-1")
    build = described_class.read(@tree, target)
    expect(build.plan.entries.map(&:source)).to eq(["rock-a"])
    expect(build.built?).to be(false)
  end

  it "keeps only the records at the planned versions: an interrupted rebuild's old record is not the release's" do
    plan("rock-a" => "1.0-2", "rock-b" => "2.0-1")
    results("rock-a" => "1.0-1", "rock-b" => "2.0-1", "rock-gone" => "3.0-1")
    build = described_class.read(@tree, target)
    expect(build.results.entries.map(&:source)).to eq(["rock-b"])
    expect(build).to be_built
    expect(build).to be_frozen
  end

  it "refuses results without the plan they were built from" do
    FileUtils.mkdir_p(dir)
    results("rock-a" => "1.0-1")
    expect { described_class.read(@tree, target) }.to raise_error(Relspec::BuildError, /plan.yml does not exist/)
  end
end
