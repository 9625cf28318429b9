# frozen_string_literal: true

require "spec_helper"
require "yaml"
require_relative "../../support/build_release"

# `relspec build` killed in the middle (SIGINT, SIGKILL) and run again:
# what finished is not rebuilt, the rest is. Real builds (host backend) of
# packages compiled from a generated workspace, in a real child process.
RSpec.describe "resuming relspec build", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-resume")
    @release = BuildRelease.new(@dir, "resume")
    @release.package("base/a1")
    @release.package("base/a2")
    # Last in the plan (dependencies first, then by name): still building
    # when the run is stopped.
    @release.package("base/zslow", cmake: "execute_process(COMMAND sleep 6)")
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def results_path
    File.join(@release.target_dir, "build-results.yml")
  end

  def packages
    File.exist?(results_path) ? YAML.safe_load(File.read(results_path)).fetch("packages") : {}
  end

  def start_build
    Process.spawn({ "XDG_CACHE_HOME" => CliRunner::CACHE }, RbConfig.ruby, BuildRelease::EXE, "build",
                  "specs/resume.yml", "--out", "out", "--backend", "host", "--jobs", "1",
                  chdir: @dir, out: File.join(@dir, "stdout"), err: File.join(@dir, "stderr"), pgroup: true)
  end

  # Waits (bounded) until the slow package's build has begun.
  def wait_for_slow_build
    log = File.join(@release.target_dir, "logs", "#{@release.source('base/zslow')}.log")
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 120
    sleep 0.2 until (File.exist?(log) && File.read(log).include?("dpkg-buildpackage")) ||
                    Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    expect(File.read(log)).to include("dpkg-buildpackage")
  end

  it "stops on SIGINT with exit status 130, keeping what finished" do
    pid = start_build
    wait_for_slow_build
    Process.kill("INT", pid)
    _, status = Process.wait2(pid)
    expect(status.exitstatus).to eq(130)
    expect(File.read(File.join(@dir, "stderr"))).to eq("relspec: interrupted\n")
    # stdout is a file: the progress lines of what started and ended
    expect(File.read(File.join(@dir, "stdout")).lines).to all(match(%r{\Abookworm/amd64(: | \[\d+/\d+\] (started|built) )}))
    expect(packages.transform_values { |record| record["status"] })
      .to eq(@release.source("base/a1") => "built", @release.source("base/a2") => "built")
  end

  it "finishes after SIGKILL without rebuilding what was built" do
    # Start over: a1 and a2 are built by the run that is killed.
    FileUtils.rm_rf([results_path, File.join(@release.target_dir, "logs")])
    pid = start_build
    wait_for_slow_build
    before = packages
    expect(before.keys).to eq([@release.source("base/a1"), @release.source("base/a2")])
    debs = Dir.glob(File.join(@release.target_dir, "results", "*", "*.deb")).to_h { |deb| [deb, File.mtime(deb)] }
    Process.kill("KILL", pid)
    Process.wait2(pid)

    run = relspec("build", "specs/resume.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    expect(run.stdout).to include("bookworm/amd64: 1 built, 2 already built, 0 failed, 0 skipped")
    after = packages
    expect(after.keys).to eq([@release.source("base/a1"), @release.source("base/a2"), @release.source("base/zslow")])
    %w[base/a1 base/a2].each { |name| expect(after[@release.source(name)]).to eq(before[@release.source(name)]) }
    debs.each { |deb, mtime| expect(File.mtime(deb)).to eq(mtime) }
    expect(after[@release.source("base/zslow")]["status"]).to eq("built")
  end

  it "rebuilds a package whose recorded file changed" do
    deb = Dir.glob(File.join(@release.target_dir, "results", @release.source("base/a1"), "*.deb")).first
    File.write(deb, "tampered", mode: "ab")
    run = relspec("build", "specs/resume.yml", "--out", "out", "--backend", "host", "--format", "json", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    report = JSON.parse(run.stdout).first
    expect(report.fetch("target")).to eq("bookworm/amd64")
    record = report.fetch("packages").fetch(@release.source("base/a1"))
    expect(record.fetch("status")).to eq("built")
    file = record.fetch("files").find { |entry| entry["name"].end_with?(".deb") }
    expect(Digest::SHA256.file(deb).hexdigest).to eq(file.fetch("sha256"))
  end

  def build_text
    run = relspec("build", "specs/resume.yml", "--out", "out", "--backend", "host", chdir: @dir)
    expect(run.exit_code).to eq(0), run.stderr
    run.stdout[%r{bookworm/amd64: .*\)}]
  end

  it "keeps the records of packages a narrowed plan leaves out, and builds nothing again when it widens" do
    spec = File.read(@release.spec_path)
    File.write(@release.spec_path, "#{spec}select: [base/a1]\n")
    compile = relspec("compile", "specs/resume.yml", "--out", "out", chdir: @dir)
    expect(compile.exit_code).to eq(0), compile.stderr
    expect(build_text).to start_with("bookworm/amd64: 0 built, 1 already built")
    expect(packages.keys.sort).to eq(%w[base/a1 base/a2 base/zslow].map { |name| @release.source(name) })
    File.write(@release.spec_path, spec)
    expect(relspec("compile", "specs/resume.yml", "--out", "out", chdir: @dir).exit_code).to eq(0)
    expect(build_text).to start_with("bookworm/amd64: 0 built, 3 already built")
  end

  it "builds again a source package rewritten at the same version, and only it" do
    # what compile does when the packaging changes but the version does not
    # (no lock history): other bytes of the .dsc, the same name
    dsc = Dir.glob(File.join(@release.target_dir, @release.source("base/a2"), "*.dsc")).first
    File.write(dsc, "#{File.read(dsc).chomp}\nX-Relspec-Test: rewritten\n")
    expect(build_text).to start_with("bookworm/amd64: 1 built, 2 already built")
    expect(packages.fetch(@release.source("base/a2")).fetch("dsc_sha256")).to eq(Digest::SHA256.file(dsc).hexdigest)
  end
end
