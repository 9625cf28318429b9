# frozen_string_literal: true

require "spec_helper"
require "relspec/diff"

# A 400-package release with 50 rebuilt packages per target (generated
# locks, written by the real LockGenerator and read by the real parser):
# the Markdown comment stays readable and under GitHub's limit.
RSpec.describe "relspec diff of large releases" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-diff-size")
    @old, @new = LargeLocks.write(@dir)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def diffs
    planner = ->(_) { raise "no spec is planned here" }
    old, new = [@old, @new].map { |path| Relspec::Diff::Input.snapshot(path, planner: planner) }
    [Relspec::Diff::ReleaseDiff.compare(old, new)]
  end

  it "puts the summary first and folds the details, under GitHub's comment limit" do
    text = Relspec::Diff::MarkdownRenderer.new.render(diffs)
    expect(text.size).to be <= Relspec::Diff::MarkdownRenderer::COMMENT_LIMIT
    expect(text.lines.first).to eq("### big\n")
    expect(text).to include("- **bionic/amd64**: 50 rebuilt (+50), 0 added, 0 removed, 9 other changes\n")
    expect(text).to match(/^- 100 new builds in all$/)
    expect(text).to include("- 50 rebuilt because generated/package_with_a_long_name_0000 is blacklisted by")
    expect(text.index("<details>")).to be > text.index("**Why**")
    expect(text.scan("<details>").size).to eq(text.scan("</details>").size)
  end

  it "leaves out details with a note rather than exceeding a smaller limit" do
    text = Relspec::Diff::MarkdownRenderer.new(limit: 12_000).render(diffs)
    expect(text.size).to be <= 12_000
    expect(text).to include("- **buster/amd64**: 50 rebuilt (+50)")
    expect(text).to match(/_Details left out \(\d+ rows and 1 more target\): this comment would exceed 12000 characters/)
    expect(text.scan("<details>").size).to eq(text.scan("</details>").size)
  end

  it "exits 1 with --fail-on-rebuilds below the number of new builds" do
    run = relspec("diff", @old, @new, "--fail-on-rebuilds", "99", "--format", "json")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("100 rebuilds, more than the 99 allowed")
    expect(JSON.parse(run.stdout)["rebuilds"]).to eq(100)
    expect(relspec("diff", @old, @new, "--fail-on-rebuilds", "100").exit_code).to eq(0)
    negative = relspec("diff", @old, @new, "--fail-on-rebuilds", "-1")
    expect([negative.stderr, negative.exit_code]).to eq(["relspec: error: --fail-on-rebuilds must be 0 or more, not -1\n", 1])
  end
end
