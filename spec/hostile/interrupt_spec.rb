# frozen_string_literal: true

require "spec_helper"
require "digest"
require "relspec/debian/orig_cache"

# Interrupts at any moment (issue 12, case 4): SIGINT is always "interrupted"
# and exit 130 (never a NameError from a half-loaded class), and the
# temporaries of a killed compile are removed by the next one, which ends
# with the tree a clean compile writes. Temporaries of a process that still
# runs are left alone, those of an earlier process that had the same pid are
# not.
RSpec.describe "relspec under interrupts" do
  # One fixture for both (making it is most of the time); each example
  # writes output folders of its own.
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-interrupt")
    @spec = ReleaseFixture.new(@dir).standalone("h", select: ["base/types", "tools/orocos.rb"], targets: "bionic: [amd64]")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def spawn_compile(out)
    spawn_relspec("compile", @spec, "--out", out, "--no-check", "--jobs", "2", chdir: @dir)
  end

  def tree(out)
    Dir.glob("**/*", File::FNM_DOTMATCH, base: File.join(@dir, out)).reject { |p| p.end_with?(".") }.sort.to_h do |path|
      file = File.join(@dir, out, path)
      [path, File.file?(file) ? Digest::SHA256.file(file).hexdigest : :dir]
    end
  end

  it "answers SIGINT with 'interrupted' and 130 at every moment of a compile" do
    (1..12).map { |i| i * 0.15 }.each do |delay|
      pid = spawn_compile("interrupted")
      sleep(delay)
      signal_relspec(pid, "INT")
      run = finish_relspec(pid)
      status = run.status
      message = run.stderr
      next if status.success? # finished before the signal: nothing to judge
      # Before the first line of relspec runs, Ruby's and Bundler's own boot
      # handle SIGINT their way (killed by the signal, or Bundler's message):
      # that window ends before exe/relspec starts, and is not judged here.
      next unless message.match?(%r{(exe|lib)/relspec|relspec: })

      expect([status.exitstatus, message]).to eq([130, "relspec: interrupted\n"]), "after #{delay} s: #{message}"
    end
  end

  # Issue 34, case 15: SIGINT while relspec's main thread waits in Open3
  # for a tool (git, made slow by a wrapper first in PATH so that it surely
  # does): Open3's reader threads, their pipes closed as the run unwound,
  # printed `#<Thread:… open3.rb:296 run> terminated with exception` before
  # the one line (3 of 3 runs before the fix).
  it "prints no thread's exception report when interrupted while a tool runs" do
    project = File.join(@dir, "git-project")
    FileUtils.mkdir_p([File.join(project, "specs"), File.join(project, "bin")])
    File.write(File.join(project, "specs", "g.yml"), "release: g\ntargets: { bookworm: [amd64] }\n")
    system("git", "-C", project, "init", "-q", exception: true)
    system("git", "-C", project, "add", "specs", exception: true)
    system("git", "-C", project, "-c", "user.email=t@example.org", "-c", "user.name=t", "commit", "-qm", "spec",
           exception: true)
    started = File.join(project, "git-started")
    File.write(File.join(project, "bin", "git"), "#!/bin/sh\ntouch #{started}\nsleep 2\nexec /usr/bin/git \"$@\"\n")
    File.chmod(0o755, File.join(project, "bin", "git"))
    pid = spawn_relspec("diff", "--base", "HEAD", "specs/g.yml", chdir: project,
                                                                 env: { "PATH" => "#{project}/bin:#{ENV.fetch('PATH')}" })
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep(0.02) until File.exist?(started) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    sleep(0.2) # into Open3's wait
    signal_relspec(pid, "INT")
    run = finish_relspec(pid)
    expect([run.status.exitstatus, run.stderr]).to eq([130, "relspec: interrupted\n"])
  end

  # Issue 24, item 4: the orig cache (<out>/<release>/.orig/) holds each
  # tarball with its SHA256; a compile killed while writing one leaves a
  # temporary, never a half-written entry, and the next compile ends with
  # every entry intact.
  it "keeps the orig cache intact when a compile is killed while writing it" do
    cache = File.join(@dir, "orig-killed", "h", ".orig")
    pid = spawn_compile("orig-killed")
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 120
    until Dir.glob(File.join(cache, "*", ".*.relspec-#{pid}-*")).any? # .orig/<key>/
      raise "no orig cache temporary appeared" if Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    end
    signal_relspec(pid, "KILL")
    finish_relspec(pid)

    run = relspec("compile", @spec, "--out", "orig-killed", "--no-check", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    entries = Dir.glob(File.join(cache, "*", "*.orig.tar.gz"))
    expect(entries).not_to be_empty
    entries.each { |entry| expect(Relspec::Debian::OrigCache.state(entry)).to eq(:intact), entry }
    expect(Dir.glob("**/.*relspec-*", File::FNM_DOTMATCH, base: cache)).to eq([])
  end

  it "removes the temporaries of a killed compile, only those, and ends with a clean compile's tree" do
    expect(relspec("compile", @spec, "--out", "clean", "--no-check", chdir: @dir).exit_code).to eq(0)
    target = File.join(@dir, "out", "h", "bionic-amd64")
    FileUtils.mkdir_p(target)
    # a temporary of a process that still runs (this one): not ours to remove
    alive = Relspec::Temporaries.path(target, "rock-h-base-types")
    Dir.mkdir(alive)
    # one left by an earlier process that had this one's pid (a reboot, a
    # wrap-around): its start time is not this process's, so it is stale
    reused = File.join(target, ".rock-h-base-types.relspec-#{Process.pid}-1-0badcafe")
    Dir.mkdir(reused)
    pid = spawn_compile("out")
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    until Dir.glob(File.join(target, ".*.relspec-#{pid}-*")).any?
      raise "no temporary appeared" if Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline

      sleep(0.01)
    end
    signal_relspec(pid, "KILL")
    finish_relspec(pid)
    expect(Dir.glob(File.join(target, ".*.relspec-#{pid}-*"))).not_to be_empty

    run = relspec("compile", @spec, "--out", "out", "--no-check", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(Dir.exist?(alive)).to be(true)
    expect(Dir.exist?(reused)).to be(false)
    Dir.rmdir(alive)
    expect(tree("out")).to eq(tree("clean"))
  end
end
