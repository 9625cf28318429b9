# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "relspec/builder"
require_relative "../../support/build_release"

# The scheduler with the host backend on small real packages that relspec
# compiled from a generated autoproj workspace: each is really built by
# dpkg-buildpackage.
RSpec.describe "relspec build scheduling (host backend)", order: :defined do
  # Records when each package started and finished (monotonic seconds).
  class BuildEventLog
    attr_reader :events

    def initialize
      @events = []
      @lock = Mutex.new
    end

    def start(*); end

    def building(entry)
      add(:start, entry.source)
    end

    def finished(outcome)
      add(:finish, outcome.entry.source)
    end

    def index(kind, source)
      @events.index { |event| event[0] == kind && event[1] == source }
    end

    private

    def add(kind, source)
      @lock.synchronize { @events << [kind, source] }
    end
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-build-scheduler")
    @release = BuildRelease.new(@dir, "sched")
    # slow and quick have no dependency; after needs quick; broken fails
    # (dpkg-buildpackage: cmake stops), its reverse dependencies come in two
    # levels; apart is independent of all of them.
    @release.package("base/slow", cmake: "execute_process(COMMAND sleep 12)")
    @release.package("base/quick")
    @release.package("base/after", dependencies: ["base/quick"])
    @release.package("base/broken", cmake: 'message(FATAL_ERROR "this package does not build")')
    @release.package("base/user", dependencies: ["base/broken"])
    @release.package("base/user2", dependencies: ["base/user"])
    @release.package("base/apart")
    @release.compile
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  def results
    YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))
  end

  def source(package)
    @release.source(package)
  end

  def build(**options)
    log = BuildEventLog.new
    reports = Relspec::Builder.run(@release.spec_path, out: File.join(@dir, "out"), backend: "host", listener: log,
                                                       **options)
    [reports.first, log]
  end

  it "starts a package as soon as its build-dependencies are built, and goes on after a failure with --keep-going" do
    report, log = build(jobs: 2, keep_going: true)
    packages = results.fetch("packages")

    # Dependency order: after starts only when quick is done, and already
    # while slow still builds (no waiting for a whole wave).
    expect(log.index(:start, source("base/after"))).to be > log.index(:finish, source("base/quick"))
    expect(log.index(:start, source("base/after"))).to be < log.index(:finish, source("base/slow"))

    expect(packages.transform_values { |record| record["status"] }).to eq(
      source("base/slow") => "built", source("base/quick") => "built", source("base/after") => "built",
      source("base/apart") => "built", source("base/broken") => "failed", source("base/user") => "skipped",
      source("base/user2") => "skipped"
    )
    # The failure names the package, the tool, its exit status and the log.
    expect(packages[source("base/broken")]["reason"]).to eq(
      "#{source('base/broken')}: dpkg-buildpackage failed (exit status 2), see logs/#{source('base/broken')}.log"
    )
    expect(File.read(File.join(@release.target_dir, "logs", "#{source('base/broken')}.log")))
      .to include("this package does not build")
    # Reverse dependencies, also indirect ones, name the failed package.
    expect(packages[source("base/user2")]["reason"]).to eq("build-dependency #{source('base/broken')} failed")
    expect(packages[source("base/user")]).not_to include("duration", "log", "files")

    # Built files are where the results say, with those bytes.
    packages.select { |_, record| record["status"] == "built" }.each do |name, record|
      expect(record["files"].map { |file| file["name"] }).to include(a_string_matching(%r{\Aresults/#{name}/.*\.deb\z}))
      record["files"].each do |file|
        path = File.join(@release.target_dir, file["name"])
        expect(Digest::SHA256.file(path).hexdigest).to eq(file["sha256"])
      end
    end
    expect(report.failed?).to be(true)

    # A package that depends on one built here sees its files (under /opt,
    # in the build's own mount namespace), and this machine's /opt is untouched.
    expect(File.read(File.join(@release.target_dir, "logs", "#{source('base/after')}.log")))
      .to include("dpkg-deb -x", "#{source('base/quick')}_")
    expect(File.exist?("/opt/rock/sched")).to be(false)
  end

  it "rebuilds nothing that finished, and without --keep-going starts nothing new after a failure" do
    before = results.fetch("packages")
    _, log = build(jobs: 1)
    after = results.fetch("packages")
    built = before.select { |_, record| record["status"] == "built" }.keys
    built.each { |name| expect(after[name]).to eq(before[name]) }
    # Only the failed package ran again; it failed first, so its reverse
    # dependencies are skipped and nothing else was left to start.
    expect(log.events.select { |kind, _| kind == :start }.map(&:last)).to eq([source("base/broken")])
    expect(after[source("base/user")]["reason"]).to eq("build-dependency #{source('base/broken')} failed")
  end
end
