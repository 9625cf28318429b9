# frozen_string_literal: true

require "spec_helper"
require_relative "../support/fixed_answer_server"
require_relative "../support/gem_osdep_release"

# A gem_source server on 127.0.0.1 whose compact index (/info/<name>) is not
# one (issue 24, item 2): `relspec plan` of a release with a gem osdep says
# which URL and line are wrong, exit 1; it never plans as if the gem had no
# versions. A real autoproj workspace and a reprepro archive without
# ruby-foo; one server, its answer changed per example.
RSpec.describe "relspec plan against a gem_source answering nonsense" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-gems")
    GemOsdepRelease.build(@dir, archive: "repos/debian", package: ["ruby-baz", "1.2.0-1"])
    @server = FixedAnswerServer.new(content_type: "text/plain")
    @url = @server.url
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "g.yml"),
               "release: g\nworkspace: ../ws/workspace\ntargets: { bookworm: [amd64] }\nmaintainer: Demo <demo@example.org>\n" \
               "gem_source: #{@url}\ndistributions:\n  bookworm: { archive: { path: ../repos/debian, trusted: true } }\n")
  end

  after(:all) do
    @server.stop
    FileUtils.rm_rf(@dir)
  end

  {
    "an HTML page" => ["<html>Sign in to the proxy</html>\n", ':1: not a compact index line ("VERSION DEPENDENCIES|checksum:SHA256"): "<html>Sign in to the proxy</html>"'],
    "a truncated index" => ["---\n1.0.0 |checksum:aa\n1.1", ':3: not a compact index line ("VERSION DEPENDENCIES|checksum:SHA256"): "1.1"']
  }.each do |what, (body, message)|
    it "names the URL and line of #{what}" do
      @server.body = body
      run = relspec("plan", "specs/g.yml", chdir: @dir)
      expect([run.exit_code, run.stdout]).to eq([1, ""]), run.stdout + run.stderr
      expect(run.stderr).to include("#{@url}/info/foo#{message}")
      expect(run.stderr).not_to include("internal error")
    end
  end
end
