# frozen_string_literal: true

require "spec_helper"
require "digest"
require "relspec/apt/repository"
require "zlib"
require_relative "../support/release_file_editor"
require_relative "../support/gem_osdep_release"

# The cache of a distribution archive's versions (Plan::ArchiveVersions,
# issue 34 cases 6-8), tried through `relspec plan` of a release whose gem
# osdep `foo` the distribution's archive provides as ruby-foo: the cache is
# untrusted and only ever a shortcut. The release's gem_source is a closed
# port, so a plan that does not find ruby-foo in the archive fails (exit 1,
# naming the URL) and one that finds it succeeds. One workspace, one
# reprepro archive and one cache folder for the file (the catalog's cache
# kept, so only the first plan loads the workspace); each example its own
# copy of the archive and an empty apt cache. The archive's Release file
# also carries text relspec prints (case 11): its control characters are
# escaped.
RSpec.describe "relspec plan with a hostile archive-versions cache", :tmpdir do
  before(:all) do
    @base = Dir.mktmpdir("relspec-hostile-archive-versions")
    GemOsdepRelease.build(@base, archive: "debian", package: ["ruby-foo", "1.2.0-1"])
  end

  after(:all) { FileUtils.rm_rf(@base) }

  INDEX = "main/binary-amd64/Packages"
  FOO = "Package: ruby-foo\nVersion: 1.2.0-1\nArchitecture: amd64\n"
  BAR = "Package: ruby-bar\nVersion: 1.0-1\nArchitecture: amd64\n"

  before do
    FileUtils.rm_rf(File.join(cache, "relspec", "apt"))
    FileUtils.cp_r(File.join(@base, "debian"), File.join(@dir, "debian"))
    FileUtils.mkdir_p(File.join(@dir, "specs"))
    File.write(File.join(@dir, "specs", "g.yml"), GemOsdepRelease.spec(@base))
  end

  def cache
    File.join(@base, "cache")
  end

  def plan
    relspec("plan", "specs/g.yml", chdir: @dir, env: { "XDG_CACHE_HOME" => cache })
  end

  # The archive's index becomes +stanzas+, as Packages and Packages.gz,
  # the Release file's checksums following.
  def index(stanzas)
    text = stanzas.join("\n")
    ReleaseFileEditor.replace_index(File.join(@dir, "debian"), "bookworm", INDEX, text)
    ReleaseFileEditor.replace_index(File.join(@dir, "debian"), "bookworm", "#{INDEX}.gz", Zlib.gzip(text))
  end

  # The archive-versions entry's path for the index as it is now.
  def entry
    archive = Relspec::Apt::Repository.new(Relspec::Apt::Fetcher.new(File.join(@dir, "debian")), trusted: true)
    File.join(cache, "relspec", "apt", archive.index_digest("bookworm", "amd64"),
              Relspec::Plan::ArchiveVersions::CACHE_ENTRY)
  end

  def planned(run)
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    run.stdout
  end

  it "plans the same again when the index holds a name with a space (case 6)" do
    index([FOO, "Package: extra foo\nVersion: 1.13.10+dfsg-2+b1\nArchitecture: amd64\n"])
    first = planned(plan)
    expect(planned(plan)).to eq(first)
    expect(File.read(entry)).not_to include("extra")
  end

  it "reads the index again when a cache line has no version (case 6)" do
    index([FOO])
    first = planned(plan)
    sha256, body = File.read(entry).split("\n", 2)
    expect(sha256).to eq(Digest::SHA256.hexdigest(body))
    body = "zzz\n#{body}"
    File.write(entry, "#{Digest::SHA256.hexdigest(body)}\n#{body}")
    expect(planned(plan)).to eq(first)
    expect(File.read(entry)).not_to include("zzz")
  end

  it "plans, with a one-line note, when a directory stands at the entry's path (case 7)" do
    index([FOO])
    FileUtils.mkdir_p(File.join(entry, "in-the-way"))
    run = plan
    expect([run.exit_code, run.stdout]).to include(0, a_string_including("tools/app"))
    expect(run.stderr).to eq("relspec: note: the cache entry #{entry} cannot be written (Is a directory); " \
                             "going on without it (only slower)\n")
  end

  it "plans, without waiting on it, when a FIFO stands at the entry's path (case 7)" do
    index([FOO])
    FileUtils.mkdir_p(File.dirname(entry))
    File.mkfifo(entry)
    pid = spawn_relspec("plan", "specs/g.yml", chdir: @dir, env: { "XDG_CACHE_HOME" => cache })
    # a plan that waits on the FIFO is killed after 60 s (and fails here)
    watchdog = Thread.new do
      sleep 60
      Process.kill("KILL", pid)
    end
    run = finish_relspec(pid)
    watchdog.kill
    expect([run.status.exited?, run.exit_code, run.stderr]).to eq([true, 0, ""])
    expect(File.file?(entry)).to be(true) # the FIFO was replaced by the entry
  end

  it "keys the entry by the index file it read, not by the first one the Release lists (case 8)" do
    # the Release lists a Packages.xz the archive does not have, before the .gz it has
    index([BAR])
    release = File.join(@dir, "debian", "dists", "bookworm", "Release")
    File.write(release, File.read(release).sub(/^SHA256:\n/, "SHA256:\n #{'0' * 64} 123 #{INDEX}.xz\n"))
    without = plan
    expect(without.exit_code).to eq(1)
    expect(without.stderr).to include("http://127.0.0.1:1")
    index([BAR, FOO])
    expect(planned(plan)).to include("tools/app")
  end

  it "prints the codename a Release file claims with its control characters escaped (case 11)" do
    release = File.join(@dir, "debian", "dists", "bookworm", "Release")
    File.write(release, File.read(release).sub("Codename: bookworm\n", "Codename: evil\e[2J\n")
                                          .sub("Suite: bookworm\n", "Suite: tri\rxie\n"))
    run = plan
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to include("the Release file is of evil\\e[2J/tri\\rxie, not bookworm")
    expect(run.stderr).not_to match(/[\e\r]/)
  end
end
