# frozen_string_literal: true

require "spec_helper"
require_relative "../support/gem_osdep_release"
require_relative "../support/full_filesystem"

# relspec's cache folder (XDG_CACHE_HOME) on a file system that takes no
# file (issue 46 case 9): a full tmpfs (ENOSPC) or a read-only one (EROFS),
# mounted for the one relspec run in a private mount namespace. A cache is
# only ever a shortcut: `relspec plan` of a release read from a real
# workspace (its catalog cache) and a reprepro archive (the archive-versions
# cache) plans as it does with a working cache, with one note on stderr.
RSpec.describe "relspec plan with a cache folder that cannot be written", :tmpdir do
  before(:all) do
    @base = Dir.mktmpdir("relspec-hostile-cache-folder")
    GemOsdepRelease.build(@base, archive: "debian", package: ["ruby-foo", "1.2.0-1"])
    FileUtils.mkdir_p(File.join(@base, "specs"))
    File.write(File.join(@base, "specs", "g.yml"), GemOsdepRelease.spec(@base))
  end

  after(:all) { FileUtils.rm_rf(@base) }

  before { skip "no user namespaces here (unshare -rm)" unless FullFilesystem.available? }

  def plan(cache, within: [])
    relspec("plan", "specs/g.yml", chdir: @base, env: { "XDG_CACHE_HOME" => cache }, within: within)
  end

  # The plan a working (empty) cache gives.
  def expected
    run = plan(File.join(@dir, "working"))
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    run.stdout
  end

  {
    full: "No space left on device",
    read_only: "Read-only file system"
  }.each do |state, reason|
    it "plans as with a working cache, with one note, when the cache's file system is #{state.to_s.tr('_', '-')}" do
      cache = File.join(@dir, state.to_s)
      FileUtils.mkdir_p(cache)
      run = plan(cache, within: FullFilesystem.command(cache, state))
      expect([run.exit_code, run.stdout]).to eq([0, expected])
      expect(run.stderr).to match(%r{\Arelspec: note: the cache entry #{Regexp.escape(cache)}/relspec/\S+ cannot be written \(#{reason}\); going on without it \(only slower\)\n\z})
      expect(Dir.children(cache)).to eq([]) # the file system was the namespace's only
    end
  end
end
