# frozen_string_literal: true

require "spec_helper"
require_relative "../support/fixed_answer_server"

# `relspec check --source launchpad` against a server on 127.0.0.1 that
# answers 200 with JSON of the wrong shape (issue 24, item 2): one error
# naming the URL and the field, exit 1, never a TypeError and exit 70. The
# shapes at every level are in spec/unit/availability/launchpad_page_spec.rb;
# these are the CLI cases (entries an integer or a mapping, a truncated
# answer). One fixture and one server for all; the body changes per example.
RSpec.describe "relspec check against a Launchpad answering nonsense" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-check")
    fixture = ReleaseFixture.new(@dir)
    fixture.spec("lp", "targets: { focal: [amd64] }\nmaintainer: Demo <demo@example.org>\nselect: [base/types]\n")
    @server = FixedAnswerServer.new
  end

  after(:all) do
    @server.stop
    FileUtils.rm_rf(@dir)
  end

  {
    "entries as an integer" => ['{"total_size": 1, "entries": 7}', "entries is a number, not a list"],
    "entries as a mapping" => ['{"entries": {"binary_package_name": "cmake"}}', "entries is an object, not a list"],
    "a truncated answer" => ['{"entries": [{"binary_package_name": "cm', "the answer is not JSON"]
  }.each do |what, (body, message)|
    it "says which field is wrong with #{what}" do
      @server.body = body
      base = "#{@server.url}/1.0"
      run = relspec("check", "specs/lp.yml", "--source", "launchpad", "--launchpad-url", base, "--timeout", "2", chdir: @dir)
      expect(run.exit_code).to eq(1), run.stderr
      expect(run.stdout + run.stderr).to include("Launchpad: #{base}/ubuntu/+archive/primary?", ": #{message}")
      expect(run.stderr).not_to include("internal error")
    end
  end
end
