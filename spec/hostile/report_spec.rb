# frozen_string_literal: true

require "spec_helper"
require_relative "../support/committed_releases"
require_relative "../support/demo_child_plan"
require "fileutils"

# `relspec report` over a build's logs it did not make and a report folder
# it does not own (issue 46, cases 2, 3 and 10): the shipped demo's specs
# and locks, and a last build of demo-child in which base/types failed,
# with its log. Links out of the output tree are refused, naming the link,
# before anything is read through them or written; a log of any size is
# read as a stream with a bound.
RSpec.describe "relspec report over hostile logs and folders" do
  around do |example|
    Dir.mktmpdir("relspec-hostile-report") do |root|
      @root = root
      @outside = File.join(root, "outside")
      FileUtils.mkdir_p(@outside)
      File.write(File.join(@outside, "precious.txt"), "mine\n")
      demo_child_failed
      example.run
    end
  end

  let(:target) { File.join(@root, "out", "demo-child", "bookworm-amd64") }
  let(:source) { "rock-demo-child-base-types" }
  let(:log) { File.join(target, "logs", "#{source}.log") }
  let(:report) { File.join(@root, "out", "demo-child", "report") }
  # as messages name them: relative to the folder relspec runs in
  let(:shown_target) { "out/demo-child/bookworm-amd64" }
  let(:shown_report) { "out/demo-child/report" }

  def demo_child_failed
    CommittedReleases.project(@root, %w[demo-base demo-child])
    FileUtils.mkdir_p(File.dirname(log))
    File.write(log, "$ dpkg-buildpackage\nCMake Error at CMakeLists.txt:3 (message):\n  types are broken\n")
    File.write(File.join(target, "build-results.yml"), <<~YAML)
      relspec_build_results: 1
      release: demo-child
      target: bookworm/amd64
      backend: host
      packages:
        #{source}:
          package: base/types
          version: 2.0-1~bookworm
          status: failed
          log: logs/#{source}.log
          reason: "#{source}: dpkg-buildpackage failed"
    YAML
    DemoChildPlan.write(target)
  end

  def report_run
    relspec("report", "specs/demo-child.yml", "--out", "out", chdir: @root)
  end

  def expect_outside_untouched
    expect(Dir.children(@outside).sort).to eq(Dir.children(@outside).sort & ["precious.txt", "#{source}.log"])
    expect(File.read(File.join(@outside, "precious.txt"))).to eq("mine\n")
  end

  it "starts from a page with the failure's first error line and a copy of its log" do
    run = report_run
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    expect(File.read(File.join(report, "index.html"))).to include("CMake Error at CMakeLists.txt:3 (message):")
    expect(File.read(File.join(report, "logs", "bookworm-amd64", "#{source}.log"))).to eq(File.read(log))
  end

  it "case 2: refuses a build's log that is a link out of the output tree, and puts nothing of its target on the page" do
    File.write(File.join(@outside, "precious.txt"), "error: the secret of another file\n")
    File.delete(log)
    File.symlink(File.join(@outside, "precious.txt"), log)
    run = report_run
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: #{shown_target}/logs/#{source}.log is a symbolic link (to #{@outside}/precious.txt): " \
                             "the report reads a build's logs only inside #{shown_target}, never through a link; remove " \
                             "the link and build again\n")
    expect(File.exist?(report)).to be(false)
  end

  it "case 2: refuses a logs/ folder that is a link, and copies none of the files it leads to" do
    FileUtils.mv(log, File.join(@outside, "#{source}.log"))
    FileUtils.rm_rf(File.dirname(log))
    File.symlink(@outside, File.dirname(log))
    run = report_run
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to start_with("relspec: error: #{shown_target}/logs is a symbolic link (to #{@outside}): the " \
                                     "report reads a build's logs only inside #{shown_target}")
    expect(File.exist?(report)).to be(false)
  end

  it "case 3: refuses a report/logs that is a link, and deletes nothing of the folder it leads to" do
    FileUtils.mkdir_p(report)
    File.symlink(@outside, File.join(report, "logs"))
    run = report_run
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: #{shown_report}/logs is a symbolic link (to #{@outside}): relspec writes " \
                             "the report only inside #{shown_report} and never through a link (its clean-up would delete the " \
                             "files the link leads to); remove the link and run again\n")
    expect(Dir.children(@outside)).to eq(["precious.txt"])
    expect_outside_untouched
    expect(Dir.children(report)).to eq(["logs"])
  end

  # A sparse log of 1 GiB: its first error line within the bound is found,
  # the copy is whole, and memory stays far below the log's size (before:
  # the log was read whole, 1.1 GB).
  it "case 10: reads a 1 GiB log as a stream: the first error line within the bound, memory bounded" do
    File.open(log, "wb") do |file|
      file.write("$ dpkg-buildpackage\n")
      file.write("compiling a line of an ordinary build log\n" * 200_000) # 8.4 MB of lines before the error
      file.write("CMake Error at CMakeLists.txt:7 (message):\n  found in a large log\n")
      file.truncate((1024 * 1024 * 1024) - 64)
      file.seek(0, IO::SEEK_END)
      file.write("\nerror: a later error, past the bound: never shown\n")
    end
    run = report_run
    expect([run.exit_code, run.stderr]).to eq([0, ""])
    page = File.read(File.join(report, "index.html"))
    expect(page).to include("CMake Error at CMakeLists.txt:7 (message):\nfound in a large log")
    expect(page).not_to include("past the bound")
    expect(File.size(File.join(report, "logs", "bookworm-amd64", "#{source}.log"))).to eq(File.size(log))
    expect(run.max_rss_kib).to be < 250 * 1024
  end
end
