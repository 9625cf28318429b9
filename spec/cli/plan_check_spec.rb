# frozen_string_literal: true

require "spec_helper"

# How `relspec plan` tells a wrong use apart (the gate itself runs in
# spec/ci_workflow_spec.rb and spec/readme_spec.rb).
RSpec.describe "relspec plan usage" do
  it "needs exactly one spec without --check" do
    run = relspec("plan")
    expect([run.stderr, run.exit_code]).to eq(["relspec: error: relspec plan needs one SPEC (or --check [SPEC...])\n", 1])
    expect(relspec("plan", "specs/demo-base.yml", "specs/demo-child.yml").exit_code).to eq(1)
  end

  it "says so when --check finds no specs/ folder" do
    Dir.mktmpdir do |dir|
      run = relspec("plan", "--check", chdir: dir)
      expect(run.stderr).to eq("relspec: error: no specs/ folder here: run from the project root or name the spec files\n")
      expect(run.exit_code).to eq(1)
    end
  end
end
