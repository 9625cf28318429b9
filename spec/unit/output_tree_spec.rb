# frozen_string_literal: true

require "relspec/output_tree"
require "relspec/target"

# Where compile writes and build and publish read: in memory.
RSpec.describe Relspec::OutputTree do
  let(:tree) { described_class.new("build", "demo") }
  let(:target) { Relspec::Target.new("bookworm", "amd64") }

  it "spells every path of a release's output once" do
    expect(tree.release_dir).to eq("build/demo")
    expect(tree.orig_cache).to eq("build/demo/.orig")
    expect(tree.target_dir(target)).to eq("build/demo/bookworm-amd64")
    expect(tree.source_dir(target, "rock-demo-base-types")).to eq("build/demo/bookworm-amd64/rock-demo-base-types")
    expect(tree.plan_file(target)).to eq("build/demo/bookworm-amd64/plan.yml")
    expect(tree.results_file(target)).to eq("build/demo/bookworm-amd64/build-results.yml")
    expect(tree.logs_dir(target)).to eq("build/demo/bookworm-amd64/logs")
    expect(tree.report_dir).to eq("build/demo/report")
    expect(tree).to be_frozen
  end

  it "keeps an absolute --out absolute" do
    expect(described_class.new("/srv/out", "demo").plan_file(target)).to eq("/srv/out/demo/bookworm-amd64/plan.yml")
  end
end
