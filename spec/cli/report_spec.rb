# frozen_string_literal: true

require "spec_helper"

# The user errors of `relspec report`; the page itself is read by a browser
# in spec/relspec/publish/example_release_spec.rb.
RSpec.describe "relspec report" do
  it "refuses a release that was never compiled, saying what to run, and writes nothing" do
    with_specs("r" => "release: r\ntargets: { bookworm: [amd64] }\nworkspace: ws\n") do |_dir, root|
      run = relspec("report", "specs/r.yml", chdir: root)
      expect([run.exit_code, run.stdout, run.stderr])
        .to eq([1, "", "relspec: error: r has no releases/r/lock.yml: run `relspec compile` first\n"])
      expect(Dir.children(root)).to eq(["specs"])
    end
  end

  it "refuses a format it does not know" do
    run = relspec("report", "specs/demo-base.yml", "--format", "pdf")
    expect([run.exit_code, run.stderr]).to eq([1, "relspec: error: Expected '--format' to be one of html, json; got pdf\n"])
  end
end
