# frozen_string_literal: true

require "spec_helper"
require "json"
require "yaml"

RSpec.describe "relspec show" do
  it "prints the effective spec of the example child as YAML" do
    run = relspec("show", "specs/demo-child.yml")
    expect(run.exit_code).to eq(0), run.stderr
    spec = YAML.safe_load(run.stdout)
    expect(spec).to include(
      "release" => "demo-child", "parent" => "demo-base", "ancestors" => ["demo-base"],
      "targets" => { "bookworm" => ["amd64"], "trixie" => ["amd64"] },
      "maintainer" => "Rock Packaging <rock-dev@example.org>",
      "blacklist" => [{ "match" => "base/types", "reason" => "the project needs the 2020 types API" }],
      "pins" => { "base/types" => { "tag" => "v2.0.0" } },
      "repository" => { "path" => "../build/repositories/demo-child", "trusted" => true,
                        "url" => "http://127.0.0.1:8000/demo-child" }
    )
    expect(spec.keys.first(3)).to eq(%w[release description parent])
  end

  it "annotates each value with where it was written with --origins" do
    run = relspec("show", "specs/demo-child.yml", "--origins")
    expect(run.exit_code).to eq(0), run.stderr
    lines = run.stdout.lines.map(&:rstrip)
    expect(lines.grep(/^targets:/).first).to match(%r{# specs/demo-base\.yml:7:1$})
    expect(lines.grep(%r{^  base/types:}).first).to match(%r{# specs/demo-child\.yml:11:3$})
    expect(lines.grep(/^release:/).first).to match(%r{# specs/demo-child\.yml:3:1$})
    expect(YAML.safe_load(run.stdout)).to eq(YAML.safe_load(relspec("show", "specs/demo-child.yml").stdout))
  end

  it "gives the spec and origins as JSON" do
    run = relspec("show", "specs/demo-child.yml", "--origins", "--format", "json")
    document = JSON.parse(run.stdout)
    expect(document["spec"]["package_prefix"]).to eq("rock")
    expect(document["origins"]).to include("package_prefix" => "specs/demo-base.yml:17:1",
                                           "pins.base/types" => "specs/demo-child.yml:11:3")
  end

  it "prints the same bytes every time" do
    outputs = Array.new(2) { relspec("show", "specs/demo-child.yml", "--origins").stdout }
    expect(outputs.uniq.size).to eq(1)
  end

  it "refuses an invalid spec with its diagnostics and prints no spec" do
    run = relspec("show", "spec/fixtures/specs/bad/unknown-parent.yml")
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).to eq(File.read(File.join(CliRunner::ROOT, "spec/fixtures/specs/bad/unknown-parent.err")))
  end
end
