# frozen_string_literal: true

require "spec_helper"
require "yaml"

# The workflow of docs/ci.md, run as GitHub would run its relspec steps
# (not GitHub itself: no Actions, no `gh`): in a project with an origin
# remote holding main, on a pull-request branch that changes a spec.
RSpec.describe "the CI workflow of docs/ci.md" do
  workflow = YAML.safe_load(File.read(File.join(CliRunner::ROOT, "docs", "ci.md"))[/## The workflow.*?```yaml\n(.*?)```/m, 1])
  steps = workflow.dig("jobs", "review", "steps").select { |step| step["run"].to_s.include?("relspec") }

  before(:all) do
    @dir = Dir.mktmpdir("relspec-ci")
    @project_dir = File.join(@dir, "project")
    FileUtils.mkdir_p(@project_dir)
    @project = DiffProject.new(@project_dir)
    GitProject.git(@dir, "clone", "--quiet", "--bare", @project_dir, "origin.git")
    @project.git("remote", "add", "origin", File.join(@dir, "origin.git"))
    @project.git("fetch", "--quiet", "origin")
    @project.git("checkout", "--quiet", "-b", "pull-request")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  after { @project.git("reset", "--quiet", "--hard", "origin/main") }

  # Each step's script under bash -e, as Actions runs it; relspec is this
  # checkout's executable. Returns [output, status] per step name.
  def run_steps(steps)
    relspec = "#{RbConfig.ruby} #{CliRunner::EXE}"
    steps.to_h do |step|
      script = step["run"].gsub("${{ github.base_ref }}", "main").gsub("bundle exec relspec", relspec)
      output, status = Open3.capture2e({ "XDG_CACHE_HOME" => CliRunner::CACHE }, "bash", "-e", "-c", script, chdir: @project_dir)
      [step["name"], [output, status]]
    end
  end

  it "has the gate, the markdown diff and the rebuild budget" do
    expect(steps.map { |step| step["name"] }).to eq(["committed release state is current", "release diff", "rebuild budget"])
    # YAML 1.1 reads the key `on` as true, as GitHub documents
    expect(workflow.fetch(true).dig("pull_request", "paths")).to include("specs/**")
  end

  it "passes a pull request with its locks recorded, and writes the markdown comment" do
    @project.spec("child", "#{DiffProject::CHILD}blacklist: [{ match: base/logging, reason: must be rebuilt }]\n")
    @project.write_lock("child")
    GitProject.commit_all(@project_dir, "child: rebuild base/logging")

    results = run_steps(steps)
    results.each { |name, (output, status)| expect(status).to be_success, "#{name}: #{output}" }
    comment = File.read(File.join(@project_dir, "release-diff.md"))
    expect(comment).to start_with("### child\n")
    expect(comment).to include("blacklist entry `base/logging` added")
    expect(comment).to include("| `base/logging` | inherit → build |")
    expect(JSON.parse(File.read(File.join(@project_dir, "release-diff.json")))["rebuilds"]).to be_positive
  end

  it "fails the gate when a spec changed but its lock was not recorded" do
    @project.spec("child", "#{DiffProject::CHILD}blacklist: [{ match: base/logging, reason: must be rebuilt }]\n")
    GitProject.commit_all(@project_dir, "child: lock forgotten")

    output, status = run_steps(steps.first(1)).fetch("committed release state is current")
    expect(status.exitstatus).to eq(1)
    expect(output).to include("releases/child/lock.yml: out of date")
    expect(output).to include("the spec (or one of its ancestors' specs) changed")
    expect(output).to match(%r{inherit → build\s+base/logging})
    # depends: follows the decisions here: not a reason of its own
    expect(output).not_to include("recorded dependencies")
  end

  it "writes the no-change note when the pull request changes no release" do
    GitProject.commit_all(@project_dir, "nothing")
    results = run_steps(steps)
    results.each { |name, (output, status)| expect(status).to be_success, "#{name}: #{output}" }
    expect(File.read(File.join(@project_dir, "release-diff.md"))).to eq("relspec: no release changes.\n")
  end
end
