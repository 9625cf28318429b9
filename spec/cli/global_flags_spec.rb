# frozen_string_literal: true

require "spec_helper"

# Options every command has may also come before the command, as people
# type them (`relspec --debug compile SPEC`).
RSpec.describe "relspec global flags" do
  it "takes --debug and --quiet before the command" do
    run = relspec("--debug", "--quiet", "validate", "specs/demo-base.yml")
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(run.stdout).to include("1 spec valid: specs/demo-base.yml")
    expect(run.stdout).not_to include("Usage:")
  end

  it "still shows the help when only flags are given" do
    run = relspec("--debug")
    expect(run.stdout).to include("relspec validate")
  end
end
