# frozen_string_literal: true

require "spec_helper"
require "json"
require "digest"

RSpec.describe "relspec validate" do
  def tree_digest(dir)
    Dir.glob("**/*", File::FNM_DOTMATCH, base: dir).sort.map do |entry|
      path = File.join(dir, entry)
      [entry, File.file?(path) ? Digest::SHA256.file(path).hexdigest : "dir"]
    end
  end

  it "accepts the example hierarchy in specs/ by default" do
    run = relspec("validate")
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to eq("2 specs valid: specs/demo-base.yml specs/demo-child.yml\n")
    expect(run.stderr).to eq("")
  end

  it "finds parents beside the named file, wherever the command runs" do
    run = relspec("validate", "demo-child.yml", chdir: File.join(CliRunner::ROOT, "specs"))
    expect(run.exit_code).to eq(0), run.stderr
  end

  it "prints warnings but exits 0 when there is no error" do
    with_specs("w" => "release: w\ntargets: { bionic: [amd64] }\nblacklist: [base/types]\n") do |_dir, root|
      run = relspec("validate", "specs/w.yml", chdir: root)
      expect(run.exit_code).to eq(0)
      expect(run.stderr).to start_with("specs/w.yml:3:13: warning[blacklist-reason]")
      expect(run.stdout).to eq("1 spec valid (1 warning): specs/w.yml\n")
    end
  end

  it "writes nothing, whether the specs are good or bad" do
    with_specs("bad" => "release: bad\ntragets: {}\n", "good" => "release: good\ntargets: { bionic: [amd64] }\n") do |_dir, root|
      before = tree_digest(root)
      expect(relspec("validate", chdir: root).exit_code).to eq(1)
      expect(relspec("validate", "specs/good.yml", chdir: root).exit_code).to eq(0)
      expect(tree_digest(root)).to eq(before)
    end
  end

  it "gives the diagnostics as data with --format json" do
    run = relspec("validate", "--format", "json", "spec/fixtures/specs/bad/unknown-key.yml")
    expect(run.exit_code).to eq(1)
    report = JSON.parse(run.stdout)
    expect(report["valid"]).to be(false)
    expect(report["diagnostics"]).to eq([{ "severity" => "error", "rule" => "unknown-key",
                                           "message" => "unknown key \"tragets\"",
                                           "file" => "spec/fixtures/specs/bad/unknown-key.yml",
                                           "line" => 3, "column" => 1, "hint" => "did you mean \"targets\"?" }])
  end

  it "says clearly when there is no specs/ folder" do
    Dir.mktmpdir do |dir|
      run = relspec("validate", chdir: dir)
      expect(run.exit_code).to eq(1)
      expect(run.stderr).to eq("relspec: error: no specs/ folder here: run from the project root or name the spec files\n")
    end
  end

  it "prints the version and help" do
    expect(relspec("--version").stdout).to eq("relspec #{Relspec::VERSION}\n")
    help = relspec("help", "validate")
    expect(help.exit_code).to eq(0)
    expect(help.stdout).to include("relspec validate [SPEC...]", "--format")
  end

  it "rejects an unknown option value without a backtrace" do
    run = relspec("validate", "--format", "xml")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to include("--format").and(include("xml"))
    expect(run.stderr).not_to match(/\.rb:\d+/)
  end
end
