# frozen_string_literal: true

require "spec_helper"
require_relative "../support/committed_releases"
require "json"

# The lock as `relspec diff` reads it (issue 34, cases 12 and 13): a value of
# the wrong type (a number as a commit or version, a null version, a
# package keyed 7, `release: 12`) is refused at lock.yml:line, exit 1; a
# package pointed at another commit or repository with every decision kept
# is a change, with `--exit-code` exit 1 and `"changed": true`. The demo's
# real lock, edited.
RSpec.describe "relspec diff on locks whose records are not what they seem", :tmpdir do
  CMAKE_VERSION = /^      version: "1\.0\.20200504\.080000-\d+~bookworm"\n/
  let(:good) { CommittedReleases.copy("demo-base/lock.yml", File.join(@dir, "good.yml")) }
  let(:text) { File.read(good) }

  # +from+: text or a Regexp (base/cmake's target version, whose Debian
  # revision bin/demo moves whenever the example's debian/ changes)
  def edited(name, from, to)
    expect(text).to match(from.is_a?(Regexp) ? from : Regexp.new(Regexp.escape(from)))
    File.write(File.join(@dir, name), text.sub(from, to))
    name
  end

  def refused(old)
    run = relspec("diff", old, good, chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""]), run.stderr
    run.stderr.lines.first
  end

  {
    "a number as a commit" => [
      "    commit: 5d62b7814c82ecaee9a897cd0e1ab3020a817196\n", "    commit: 1234567\n",
      "old.yml:9:13: error[lock]: cannot read the lock: packages.base/cmake.commit must be text, not the number 1234567\n"
    ],
    "a number as a target version" => [
      CMAKE_VERSION, "      version: 1.10\n",
      "old.yml:54:16: error[lock]: cannot read the lock: targets.bookworm/amd64.base/cmake.version must be text, " \
      "not the number 1.10\n"
    ],
    "a null target version" => [
      CMAKE_VERSION, "      version: null\n",
      "old.yml:54:16: error[lock]: cannot read the lock: targets.bookworm/amd64.base/cmake: a published decision needs a version\n"
    ],
    "a package keyed 7" => [
      "packages:\n", "packages:\n  7:\n    url: https://example.org/x.git\n",
      "old.yml:7:3: error[lock]: cannot read the lock: the key 7 in packages must be text (relspec writes it quoted: \"7\")\n"
    ],
    "release: 12" => [
      "release: demo-base\n", "release: 12\n",
      "old.yml:3:10: error[lock]: cannot read the lock: release must be text, not the number 12\n"
    ]
  }.each do |what, (from, to, message)|
    it "refuses #{what} at its line" do
      expect(refused(edited("old.yml", from, to))).to eq(message)
    end
  end

  it "reports a package pointed at another commit, every decision kept, as a change" do
    moved = edited("new.yml", "    commit: 52d727209efdb693b7fce6fa8235295c956da59b\n", "    commit: #{'a' * 40}\n")
    run = relspec("diff", good, moved, "--exit-code", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, ""])
    expect(run.stdout).to include("  base/types: source commit 52d727209efd → aaaaaaaaaaaa (no decision changed)\n")
    json = relspec("diff", good, moved, "--format", "json", chdir: @dir)
    document = JSON.parse(json.stdout)
    expect(document["changed"]).to be(true)
    commit = { "old" => "52d727209efdb693b7fce6fa8235295c956da59b", "new" => "a" * 40 }
    expect(document["releases"].first["sources"])
      .to eq([{ "package" => "base/types", "decisions_changed" => false, "fields" => { "commit" => commit } }])
  end

  it "reports a package pointed at another repository as a change" do
    moved = edited("new.yml", "    url: $AUTOPROJ_ROOT/repositories/base/types.git\n", "    url: https://evil.example.org/types.git\n")
    run = relspec("diff", good, moved, "--exit-code", chdir: @dir)
    expect([run.exit_code, run.stderr]).to eq([1, ""])
    expect(run.stdout).to include("  base/types: source url $AUTOPROJ_ROOT/repositories/base/types.git → " \
                                  "https://evil.example.org/types.git (no decision changed)\n")
  end
end
