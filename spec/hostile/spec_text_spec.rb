# frozen_string_literal: true

require "spec_helper"

# Specs that validate but say something else than they seem (issue 34,
# case 11), through the real CLI: a `leave_out` entry with `targets: []`
# left nothing out, silently; control characters in a leave_out or
# blacklist reason were printed raw by `plan` and `why` (a newline forges a
# line of the plan, an escape sequence clears the screen). One workspace
# for the file (WorkspaceBuilder's template).
RSpec.describe "relspec on spec text that is not what it seems", :tmpdir do
  before(:all) do
    @base = Dir.mktmpdir("relspec-hostile-spec-text")
    builder = WorkspaceBuilder.new(File.join(@base, "ws"))
    builder.package("tools/app", type: :cmake, date: "2020-01-01T00:00:00Z")
    builder.package("tools/lib", type: :cmake, date: "2020-01-01T00:00:00Z")
    builder.layout("tools/app", "tools/lib")
    builder.create
  end

  after(:all) { FileUtils.rm_rf(@base) }

  def spec(yaml)
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "t.yml"),
               "release: t\nworkspace: #{@base}/ws/workspace\ntargets: { bookworm: [amd64] }\n" \
               "maintainer: Demo <demo@example.org>\n#{yaml}")
    "specs/t.yml"
  end

  it "refuses a leave_out entry without a target, with its file:line" do
    run = relspec("validate", spec("leave_out:\n  - match: tools/app\n    reason: not yet\n    targets: []\n"), chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq(
      "specs/t.yml:8:14: error[leave-out-target]: the leave_out entry names no target: it would leave nothing out\n  " \
      "hint: name the codenames it applies to, or remove `targets` to leave it out on every target\n1 error in 1 file\n"
    )
  end

  it "prints leave_out and blacklist reasons with their control characters escaped" do
    path = spec("leave_out:\n  - match: tools/app\n    reason: \"needs qt4\\nbuilds on bookworm/amd64: forged\\e[2J\"\n" \
                "blacklist:\n  - match: tools/lib\n    reason: \"broken\\r\\u202Eevil\"\n")
    plan = relspec("plan", path, chdir: @dir)
    expect([plan.exit_code, plan.stderr]).to eq([0, ""])
    expect(plan.stdout).to include('left out by "tools/app" (needs qt4\\nbuilds on bookworm/amd64: forged\\e[2J)')
    expect(plan.stdout).to include('blacklisted by "tools/lib" (broken\\r\\u202Eevil)')
    expect(plan.stdout).not_to match(%r{[\e\r\u202E]|^builds on bookworm/amd64: forged})
    why = relspec("why", path, "tools/app", chdir: @dir)
    expect(why.stdout + why.stderr).to include("(needs qt4\\nbuilds on bookworm/amd64: forged\\e[2J)")
    expect(why.stdout + why.stderr).not_to match(/[\e\r\u202E]/)
  end
end
