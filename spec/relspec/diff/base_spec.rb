# frozen_string_literal: true

require "spec_helper"
require "json"

# relspec diff --base REF in a repository with several commits since REF, a
# renamed spec and a deleted one: REF is read with git only, the working
# tree, the index and HEAD stay as they were.
RSpec.describe "relspec diff --base" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-diff-base")
    @project = DiffProject.new(@dir)
    extra = "parent: base\ntargets: { bionic: [amd64] }\nmaintainer: Demo <demo@example.org>\n"
    @project.spec("extra", extra)
    @project.spec("spare", extra)
    %w[extra spare].each { |release| @project.write_lock(release) }
    GitProject.commit_all(@dir, "two more releases")
    @base = @project.git("rev-parse", "HEAD").strip

    @project.spec("child", "#{DiffProject::CHILD}blacklist: [{ match: base/logging, reason: rebuilt }]\n")
    @project.write_lock("child")
    GitProject.commit_all(@dir, "child: rebuild base/logging")

    @project.git("mv", "specs/extra.yml", "specs/renamed.yml")
    File.write(File.join(@dir, "specs", "renamed.yml"),
               File.read(File.join(@dir, "specs", "renamed.yml")).sub("release: extra", "release: renamed"))
    @project.git("rm", "--quiet", "-r", "releases/extra", "specs/spare.yml", "releases/spare")
    @project.write_lock("renamed")
    GitProject.commit_all(@dir, "rename extra, drop spare")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def diff(*args)
    relspec("diff", "--base", @base, *args, chdir: @dir)
  end

  it "compares every release with its state at the ref: changed, renamed, removed" do
    state = -> { [tree_state(@dir), @project.git("rev-parse", "HEAD")] }
    before = state.call
    run = diff("--format", "json")
    expect(run.stderr).to eq("")
    document = JSON.parse(run.stdout)
    statuses = document["releases"].to_h { |release| [release["release"], release["status"]] }
    expect(statuses).to eq("base" => "unchanged", "child" => "changed", "other" => "unchanged",
                           "renamed" => "renamed", "spare" => "removed")
    renamed = document["releases"].find { |release| release["release"] == "renamed" }
    expect(renamed["old"]).to eq("release" => "extra", "source" => "#{@base}:releases/extra/lock.yml")
    expect(renamed["spec_changes"]).to include(include("key" => "release", "old" => "extra", "new" => "renamed"))
    child = document["releases"].find { |release| release["release"] == "child" }
    expect(child["spec_changes"].map { |change| [change["key"], change["subject"], change["change"]] })
      .to eq([["blacklist", "base/logging", "added"]])
    expect(state.call).to eq(before) # not a file written, not even the index refreshed
    expect(@project.git("status", "--porcelain")).to eq("")
  end

  it "reports a lock edited by hand (another URL) as a change, with what it records, --exit-code 1" do
    lock = File.join(@dir, "releases", "base", "lock.yml")
    committed = File.read(lock)
    File.write(lock, committed.sub(/^    url: .*$/, "    url: https://evil.example.org/x.git"))
    run = relspec("diff", "--base", "HEAD", "specs/base.yml", "--exit-code", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, ""])
    expect(run.stdout).to start_with("base: HEAD:releases/base/lock.yml → specs/base.yml (planned: releases/base/lock.yml is out of date)\n  " \
                                     "base/cmake: releases/base/lock.yml records url https://evil.example.org/x.git, the plan ")
  ensure
    File.write(lock, committed)
  end

  it "limits the comparison to the specs named" do
    run = diff("specs/child.yml", "--format", "json")
    expect(JSON.parse(run.stdout)["releases"].map { |release| release["release"] }).to eq(["child"])
  end

  it "says which ref is unknown, and exits 2 with --exit-code" do
    run = relspec("diff", "--base", "no-such-ref", "--exit-code", chdir: @dir)
    expect(run.stderr).to eq("relspec: error: no-such-ref is not a commit of the git repository at .\n")
    expect(run.exit_code).to eq(2)
    expect(relspec("diff", "--base", "no-such-ref", chdir: @dir).exit_code).to eq(1)
  end
end
