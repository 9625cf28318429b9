# frozen_string_literal: true

require "spec_helper"
require "json"

# `relspec diff --base` when the working tree's lock is out of date with its
# spec, the workspace or an ancestor (issue 24, item 1): the stale side is
# planned, never read from the lock, so the diff never says "no decision
# changed" for a change that changes decisions; the markdown says which
# side was planned and which was read from a lock. Each example changes the
# committed project without `relspec plan --write` and puts it back.
RSpec.describe "relspec diff --base with a stale working-tree lock" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-stale")
    @project = DiffProject.new(@dir)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after { @project.git("checkout", "--quiet", "--", ".") }

  def child(yaml)
    File.write(File.join(@dir, "specs", "child.yml"), "release: child\nworkspace: ../ws/workspace\n#{yaml}")
  end

  def markdown
    run = relspec("diff", "--base", "HEAD", "specs/child.yml", "--format", "markdown", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("_Old: read from `HEAD:releases/child/lock.yml`; new: planned from `specs/child.yml` " \
                                  "(`releases/child/lock.yml` is out of date: run `relspec plan --write`)_")
    run.stdout
  end

  it "plans a spec whose blacklist entry was added without plan --write" do
    child("#{DiffProject::CHILD}blacklist: [{ match: base/logging, reason: rebuilt }]\n")
    text = markdown
    expect(text).to include("blacklist entry `base/logging` added (rebuilt): 2 decisions (bionic/amd64)")
    expect(text).not_to include("no decision changed")
    expect(text).to include("**bionic/amd64**")
  end

  it "plans a spec whose pin moved without plan --write" do
    child(DiffProject::CHILD.sub("{ tag: v2.0.0 }", "{ branch: master }"))
    text = markdown
    expect(text).to include("pin of `base/types` moved (tag v2.0.0 → branch master)")
    expect(text).not_to include("no decision changed")
  end

  it "plans a release whose ancestor was republished, with the text and JSON saying so" do
    @project.publish_base(older_logging: false)
    begin
      text = markdown
      expect(text).to include("**Ancestors**")
      run = relspec("diff", "--base", "HEAD", "specs/child.yml", "--format", "json", chdir: @dir)
      child = JSON.parse(run.stdout)["releases"].first
      expect(child["new"]).to eq("release" => "child", "source" => "specs/child.yml", "stale_lock" => "releases/child/lock.yml")
      expect(child["old"]).to eq("release" => "child", "source" => "HEAD:releases/child/lock.yml")
      # publish lists the repository from the lock, so it refuses this one
      # before reading any result or touching the repository
      publish = relspec("publish", "specs/child.yml", "--out", "out", chdir: @dir)
      expect([publish.exit_code, publish.stdout]).to eq([1, ""])
      expect(publish.stderr).to include("releases/child/lock.yml: error[publish-lock]: releases/child/lock.yml is out of " \
                                        "date: the repository of base on bionic holds other packages now",
                                        "hint: run relspec compile specs/child.yml (and build) again, then publish")
      expect(File.exist?(File.join(@dir, "repos", "child"))).to be(false)
    ensure
      @project.publish_base(older_logging: true)
    end
  end

  it "reads a lock that is up to date, and says nothing about planning" do
    run = relspec("diff", "--base", "HEAD", "specs/child.yml", "--format", "json", chdir: @dir)
    expect(JSON.parse(run.stdout)["releases"].first["new"]).to eq("release" => "child", "source" => "releases/child/lock.yml")
    # a current lock passes publish's check: what stops it is the missing build
    publish = relspec("publish", "specs/child.yml", "--out", "out", chdir: @dir)
    expect([publish.exit_code, publish.stderr]).to eq([1, "relspec: error: nothing to publish: no target of child has a " \
                                                          "build-results.yml under out/child (run relspec build first)\n"])
  end
end
