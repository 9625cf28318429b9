# frozen_string_literal: true

require "spec_helper"
require "json"
require "yaml"
require "pathname"
require "digest"
require_relative "../../support/build_release"
require_relative "../../support/slurm_cluster"

# `relspec build --engine slurm` on a real one-node Slurm cluster (munged,
# slurmctld, slurmd of Debian's slurm-wlm, in a private network namespace;
# SlurmCluster), building small real packages compiled from a generated
# workspace. relspec runs in the cluster's namespace, as on a login node.
RSpec.describe "relspec build --engine slurm", order: :defined do
  before(:all) do
    @cluster = SlurmCluster.start(features: %w[amd64])
    @dir = Dir.mktmpdir("relspec-build-slurm")
    @release = BuildRelease.new(@dir, "sl")
    # Three layers, one failure with two levels of reverse dependencies.
    @release.package("base/a")
    @release.package("base/b")
    @release.package("base/c", dependencies: ["base/a"])
    @release.package("base/d", dependencies: %w[base/a base/b])
    @release.package("base/e", dependencies: %w[base/c base/d])
    @release.package("base/broken", cmake: 'message(FATAL_ERROR "this package does not build")')
    @release.package("base/user", dependencies: %w[base/broken base/a])
    @release.package("base/user2", dependencies: ["base/user"])
    @release.compile
  end

  after(:all) do
    @cluster&.stop
    FileUtils.rm_rf(@dir) if @dir
  end

  def build(*args, dir: @dir, spec: "specs/sl.yml")
    @cluster.relspec("build", spec, "--out", "out", "--backend", "host", "--engine", "slurm",
                     "--slurm", "poll_interval=0.3", *args, chdir: dir)
  end

  def results(release = @release)
    YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml")))
  end

  # The .debs' SHA256 per source (.buildinfo and .changes name the build
  # folder and date, so they differ between any two builds).
  def deb_digests(packages)
    packages.transform_values do |record|
      Array(record["files"]).select { |file| file["name"].end_with?(".deb") }.to_h { |file| [file["name"], file["sha256"]] }
    end
  end

  def jobs_named(pattern)
    @cluster.jobs.select { |job| job["name"].match?(pattern) }
  end

  it "builds a layered graph as the local scheduler does, skipping exactly the failure's reverse dependencies" do
    local = relspec("build", "specs/sl.yml", "--out", "out", "--backend", "host", "--jobs", "2", "--keep-going",
                    chdir: @dir)
    expect(local.exit_code).to eq(1), local.stderr
    expected = results.fetch("packages")
    FileUtils.rm_rf(Dir.glob(File.join(@release.target_dir, "{results,logs,build-results.yml}")))

    run = build("--keep-going")
    expect(run.exit_code).to eq(1), run.stdout + run.stderr + @cluster.logs
    packages = results.fetch("packages")
    expect(results.fetch("backend")).to eq("host")
    expect(packages.transform_values { |r| [r["status"], r["version"]] })
      .to eq(expected.transform_values { |r| [r["status"], r["version"]] })
    expect(deb_digests(packages)).to eq(deb_digests(expected))
    broken = @release.source("base/broken")
    expect(packages.reject { |_, r| r["status"] == "built" }.keys)
      .to contain_exactly(broken, @release.source("base/user"), @release.source("base/user2"))
    expect(packages[broken]["reason"]).to match(%r{\A#{broken}: Slurm job \d+ FAILED \(exit status 2\), see logs/#{broken}\.log\z})
    expect(File.read(File.join(@release.target_dir, packages[broken]["log"]))).to include("this package does not build")
    expect(packages[@release.source("base/user2")]["reason"]).to eq("build-dependency #{broken} failed")
    expect(packages[@release.source("base/user")]).not_to include("files", "duration")
    # The files are where the results say, with those bytes.
    packages.each_value do |record|
      Array(record["files"]).each do |file|
        expect(Digest::SHA256.file(File.join(@release.target_dir, file["name"])).hexdigest).to eq(file["sha256"])
      end
    end

    # One job per package plus the chroot job, named release/target/source@run,
    # each build started only after the jobs of its build-dependencies ended.
    jobs = jobs_named(%r{\Asl/bookworm-amd64/}).to_h { |job| [job["name"].split("/").last.split("@").first, job] }
    expect(jobs.keys).to contain_exactly("chroot", *packages.keys)
    expect(jobs.values.map { |job| job["name"].split("@").last }.uniq.size).to eq(1)
    {
      "base/c" => %w[base/a], "base/d" => %w[base/a base/b], "base/e" => %w[base/c base/d]
    }.each do |package, deps|
      job = jobs.fetch(@release.source(package))
      deps.each do |dep|
        expect(job["start_time"]).to be >= jobs.fetch(@release.source(dep))["end_time"]
      end
      expect(job["start_time"]).to be >= jobs.fetch("chroot")["end_time"]
    end
    expect(jobs.fetch(@release.source("base/user"))["job_state"]).to eq("CANCELLED")
  end

  # Issue 34, case 10: the result files of the first example's run, forged
  # as a hostile or broken node could write them, and the results of those
  # packages forgotten: the next run does not record them as built (no
  # file; another package's .deb; a file outside the results folder) but
  # builds them again.
  it "records a job's result only when its files are that package's, in its results folder, as written" do
    dir = @release.target_dir
    file = lambda do |path, name|
      "file #{Digest::SHA256.file(path).hexdigest} #{File.size(path)} #{name}\n"
    end
    a, b, e, c = %w[base/a base/b base/e base/c].map { |name| @release.source(name) }
    c_deb = Dir.glob("results/#{c}/*.deb", base: dir).first
    outside = Pathname("/etc/hostname").relative_path_from(Pathname(File.join(dir, "results", e))).to_s
    header = "relspec_job_result 1\nstatus built\nexit 0\nduration 1.0\n"
    forged = { a => header, b => header + file.call(File.join(dir, c_deb), c_deb),
               e => header + file.call("/etc/hostname", "results/#{e}/#{outside}") }
    forged.each { |source, text| File.write(Dir.glob(File.join(dir, "slurm", "*", "#{source}.result")).first, text) }
    records = YAML.safe_load(File.read(File.join(dir, "build-results.yml")))
    forged.each_key { |source| records["packages"].delete(source) }
    File.write(File.join(dir, "build-results.yml"), YAML.dump(records))

    run = build("--keep-going")
    expect(run.exit_code).to eq(1), run.stdout + run.stderr # base/broken still fails
    packages = results.fetch("packages")
    forged.each_key do |source|
      expect(packages[source]["status"]).to eq("built")
      names = packages[source]["files"].map { |entry| entry["name"] }
      expect(names).to all(start_with("results/#{source}/#{source}_"))
      expect(names.grep(/\.deb\z/).size).to eq(1)
      expect(jobs_named(%r{\Asl/bookworm-amd64/#{source}@}).size).to eq(2) # built again
    end
  end

  it "adopts the jobs of a killed run instead of submitting them again, and loses none" do
    # issue 34, case 9: a project folder whose name sbatch would read as a
    # pattern (%j: the job id) in --output
    release = BuildRelease.new(File.join(@dir, "kill-100%j"), "slk")
    release.package("base/first", cmake: "execute_process(COMMAND sleep 4)")
    release.package("base/second", dependencies: ["base/first"])
    release.package("base/third", dependencies: ["base/second"])
    release.compile
    env, *command = @cluster.relspec_command("build", "specs/slk.yml", "--out", "out", "--backend", "host",
                                             "--engine", "slurm", "--slurm", "poll_interval=0.3", "--quiet")
    pid = Process.spawn(env, *command, chdir: release.dir, out: File::NULL, err: File::NULL)
    first = %r{\Aslk/bookworm-amd64/#{release.source('base/first')}@}
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep 0.2 until jobs_named(first).any? { |job| job["job_state"] == "RUNNING" } ||
                    Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    Process.kill("KILL", pid)
    Process.wait(pid)
    expect(jobs_named(first).map { |job| job["job_state"] }).to eq(["RUNNING"])

    run = @cluster.relspec("build", "specs/slk.yml", "--out", "out", "--backend", "host", "--engine", "slurm",
                           "--slurm", "poll_interval=0.3", chdir: release.dir)
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    expect(results(release).fetch("packages").values.map { |record| record["status"] }).to eq(%w[built built built])
    # Each package ran in exactly one job: the second relspec adopted them.
    %w[base/first base/second base/third].each do |package|
      jobs = jobs_named(%r{\Aslk/bookworm-amd64/#{release.source(package)}@})
      expect(jobs.map { |job| job["job_state"] }).to eq(["COMPLETED"]), package
    end

    # Nothing left to do: no job at all.
    count = @cluster.jobs.size
    again = @cluster.relspec("build", "specs/slk.yml", "--out", "out", "--backend", "host", "--engine", "slurm",
                             chdir: release.dir)
    expect(again.stdout).to include("0 built, 3 already built")
    expect(@cluster.jobs.size).to eq(count)
  end

  it "cancels the run's jobs on Ctrl-C and says so" do
    release = BuildRelease.new(File.join(@dir, "int"), "sli")
    release.package("base/long", cmake: "execute_process(COMMAND sleep 30)")
    release.package("base/after", dependencies: ["base/long"])
    release.compile
    env, *command = @cluster.relspec_command("build", "specs/sli.yml", "--out", "out", "--backend", "host",
                                             "--engine", "slurm", "--slurm", "poll_interval=0.3", "--quiet")
    stderr = File.join(release.dir, "stderr")
    pid = Process.spawn(env, *command, chdir: release.dir, out: File::NULL, err: stderr)
    long = %r{\Asli/bookworm-amd64/#{release.source('base/long')}@}
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep 0.2 until jobs_named(long).any? { |job| job["job_state"] == "RUNNING" } ||
                    Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    Process.kill("INT", pid)
    _, status = Process.wait2(pid)
    expect(status.exitstatus).to eq(130)
    # relspec waits, bounded, for the cancelled jobs to end before it says
    # so, and names those still ending at its deadline (a loaded machine).
    message = File.read(stderr)
    expect(message).to match(/\Arelspec: cancelled the Slurm jobs of run \h{12}: \d+(, \d+)*( \(still ending: \d+(, \d+)*; squeue shows when they have\))?\nrelspec: interrupted\n\z/)
    named = jobs_named(%r{\Asli/bookworm-amd64/rock})
    ending = message[/still ending: ([\d, ]+)/, 1].to_s.split(", ").map(&:to_i)
    # what relspec did not name as ending has ended when it exits
    expect(named.reject { |job| ending.include?(job["job_id"]) }.map { |job| job["job_state"] }).to all(eq("CANCELLED"))
    # and the rest reach their final state within a deadline, never run on
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep 0.3 until jobs_named(%r{\Asli/bookworm-amd64/rock}).none? { |job| job["job_state"] == "COMPLETING" } ||
                    Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    expect(jobs_named(%r{\Asli/bookworm-amd64/rock}).map { |job| job["job_state"] }).to eq(%w[CANCELLED CANCELLED])
  end

  it "refuses at submit an architecture no node has, leaving no job behind" do
    File.write(@release.spec_path, File.read(@release.spec_path).sub("bookworm: [amd64]", "bookworm: [amd64, arm64]"))
    compile = relspec("compile", "specs/sl.yml", "--out", "out", "--no-check", chdir: @dir)
    expect(compile.exit_code).to eq(0), compile.stderr
    run = build("--target", "bookworm/arm64")
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to eq("relspec: error: bookworm/arm64: no node of the Slurm cluster has the feature arm64 " \
                             "that builds for arm64 need (set it on the nodes that build arm64, natively or by " \
                             "emulation, or name their feature with --slurm features.arm64=NAME; docs/scale-out.md)\n")
    expect(jobs_named(%r{\Asl/bookworm-arm64/})).to eq([])
  end

  it "refuses a cluster setting it does not know, naming the file and line" do
    FileUtils.mkdir_p(File.join(@dir, ".relspec"))
    File.write(File.join(@dir, ".relspec", "slurm.yml"), "partition: build\npartiton: typo\n")
    run = build
    expect(run.exit_code).to eq(1)
    expect(run.stderr).to start_with("relspec: error: #{File.join(@dir, '.relspec', 'slurm.yml')}:2: " \
                                     "error[slurm-settings]: unknown setting \"partiton\"")
  ensure
    FileUtils.rm_rf(File.join(@dir, ".relspec"))
  end

  # The early cutoff on Slurm (docs/scale-out.md, "Early cutoff"): the
  # release of early_cutoff_build_spec.rb (base/lib, a C library; base/user,
  # which depends on it; base/app on base/user and base/lib2), built and
  # published with the local engine, then changed and built on the cluster.
  describe "the early cutoff" do
    before(:all) do
      @cut = Dir.mktmpdir("relspec-slurm-cutoff")
      @cutoff = BuildRelease.new(@cut, "sc")
      @lib_cmake = "enable_language(C)\nadd_library(cut SHARED cut.c)\n" \
                   "install(TARGETS cut LIBRARY DESTINATION lib)\ninstall(FILES cut.h DESTINATION include)"
      @cutoff.package("base/lib", cmake: @lib_cmake, files: { "cut.c" => "#include \"cut.h\"\nint cut_value(void) { return 42; }\n",
                                                              "cut.h" => "int cut_value(void);\n" })
      @cutoff.package("base/user", dependencies: ["base/lib"])
      @cutoff.package("base/lib2")
      @cutoff.package("base/app", dependencies: %w[base/user base/lib2])
      @cutoff.compile(spec: "repository: { path: ../repos/sc, trusted: true }\n")
      [%w[build --backend host], %w[publish]].each do |command, *options|
        run = relspec(command, "specs/sc.yml", "--out", "out", *options, chdir: @cut)
        raise run.stdout + run.stderr unless run.exit_code.zero?
      end
      @first = %w[base/lib base/user base/app].to_h { |package| [package, cutoff_record(package)] }
    end

    after(:all) { FileUtils.rm_rf(@cut) if @cut }

    def cutoff_record(package)
      results(@cutoff)["packages"][@cutoff.source(package)]
    end

    def change(path, content, package: "base/lib")
      @cutoff.change(package, path, content)
    end

    def cut!(*args)
      run = relspec(*args, "specs/sc.yml", "--out", "out", chdir: @cut)
      raise run.stdout + run.stderr unless run.exit_code.zero?

      run
    end

    def slurm_build(*args)
      build(*args, dir: @cut, spec: "specs/sc.yml").tap do |run|
        expect(run.exit_code).to eq(0), run.stdout + run.stderr + @cluster.logs
      end
    end

    def cutoff_jobs(package)
      jobs_named(%r{\Asc/bookworm-amd64/#{Regexp.escape(@cutoff.source(package))}@})
    end

    # A relspec killed while base/lib's job runs leaves base/user's job
    # held; the one run again adopts it, decides it and cancels it.
    it "keeps the dependents of a body-only change unbuilt, cancelling their held jobs, also when adopted" do
      lib, user = %w[base/lib base/user].map { |package| @cutoff.source(package) }
      change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 43; }\n")
      change("CMakeLists.txt", "cmake_minimum_required(VERSION 3.10)\nproject(p NONE)\n#{@lib_cmake}\n" \
                               "install(FILES base-lib.txt DESTINATION share)\nexecute_process(COMMAND sleep 4)\n")
      cut!("compile")
      env, *command = @cluster.relspec_command("build", "specs/sc.yml", "--out", "out", "--backend", "host",
                                               "--engine", "slurm", "--slurm", "poll_interval=0.3", "--quiet")
      pid = Process.spawn(env, *command, chdir: @cut, out: File::NULL, err: File::NULL)
      deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 120
      sleep 0.2 until cutoff_jobs("base/lib").any? { |job| job["job_state"] == "RUNNING" } ||
                      Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
      Process.kill("KILL", pid)
      Process.wait(pid)
      held = cutoff_jobs("base/user")
      expect(held.map { |job| [job["job_state"], job["state_reason"]] }).to eq([%w[PENDING JobHeldUser]])

      run = slurm_build
      body = cutoff_record("base/lib")
      expect(body["interface"]).to include("against" => @first["base/lib"]["version"], "verdict" => "unchanged")
      expect(body["files"].map { |file| file["name"] }).to include(a_string_ending_with(".abi.xml.gz"))
      kept = cutoff_record("base/user")
      expect(kept).to include("status" => "kept", "files" => @first["base/user"]["files"])
      expect(kept["cutoff"]).to eq("keeps" => @first["base/user"]["version"], "verdict" => "keep",
                                   "reason" => "the interface of #{lib} did not change",
                                   "evidence" => ["#{lib}: #{body['interface']['compared']} files compared with " \
                                                  "#{@first['base/lib']['version']}, unchanged"])
      expect(cutoff_record("base/app")).to include("status" => "kept")
      expect(run.stdout).to include("bookworm/amd64: 1 built, 2 kept, 0 already built, 0 failed, 0 skipped")
      # one job of base/lib, adopted; base/user's held one cancelled, never run; base/app's too
      expect(cutoff_jobs("base/lib").map { |job| job["job_state"] }).to eq(["COMPLETED"])
      expect(cutoff_jobs("base/user").map { |job| [job["job_id"], job["job_state"]] })
        .to eq([[held.first["job_id"], "CANCELLED"]])
      expect(cutoff_jobs("base/app").map { |job| job["job_state"] }).to eq(["CANCELLED"])
      %w[base/user base/app].each do |package| # no result: the job never ran
        expect(Dir.glob(File.join(@cutoff.target_dir, "slurm", "*", "#{@cutoff.source(package)}.result"))).to eq([])
      end
      expect(Dir.glob(File.join(@cutoff.target_dir, "slurm", "*", "replaced"))).to eq([])

      cut!("publish")
      expect(@cutoff.published).to include(lib => body["version"], user => @first["base/user"]["version"])
      expect(relspec("why", "specs/sc.yml", "base/user", chdir: @cut).stdout).to include("base/user is kept at #{@first['base/user']['version']} as #{user}: " \
                                                                                         "the interface of #{lib} did not change (#{lib}: ")
    end

    # base/app changes too: it names base/user's new version, so base/user
    # is built (its job released) rather than kept.
    it "builds a candidate that a package built in the run names at its new version" do
      change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 46; }\n")
      change("app.txt", "a change of base/app\n", package: "base/app")
      cut!("compile")
      run = slurm_build
      user = cutoff_record("base/user")
      expect(user["status"]).to eq("built")
      expect(user["cutoff"]).to include("verdict" => "rebuild", "reason" => "built after all: #{@cutoff.source('base/app')} " \
                                                                            "is built in this run and names its new version")
      expect(cutoff_record("base/app")["status"]).to eq("built")
      expect(run.stdout).to include("bookworm/amd64: 3 built, 0 already built, 0 failed, 0 skipped")
      cut!("publish")
      expect(@cutoff.published).to include(@cutoff.source("base/user") => user["version"],
                                           @cutoff.source("base/app") => cutoff_record("base/app")["version"])
    end

    # base/user is kept (base/lib's body changed), then base/app is decided
    # rebuild (base/lib2's installed file changed): base/app names
    # base/user's new version, so base/user's job is submitted again and
    # base/app's waits for it; the repository holds what base/app names.
    it "builds a kept candidate after all, first, when a candidate decided rebuild names its new version" do
      change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 48; }\n")
      change("base-lib2.txt", "a change of base/lib2\n", package: "base/lib2")
      cut!("compile")
      run = slurm_build
      user = cutoff_record("base/user")
      app = cutoff_record("base/app")
      expect(user["status"]).to eq("built")
      expect(user["cutoff"]).to include("verdict" => "rebuild", "reason" => "built after all: #{@cutoff.source('base/app')} " \
                                                                            "is built in this run and names its new version")
      expect(app["cutoff"]).to include("verdict" => "rebuild", "reason" => "the interface of #{@cutoff.source('base/lib2')} changed")
      expect(run.stdout).to include("bookworm/amd64: 4 built, 0 already built, 0 failed, 0 skipped")
      app_job = cutoff_jobs("base/app").max_by { |job| job["job_id"] }
      jobs = cutoff_jobs("base/user").select { |job| job["name"].end_with?(app_job["name"][/@\h+\z/]) } # this run's
                                     .sort_by { |job| job["job_id"] }
      expect(jobs.map { |job| job["job_state"] }).to eq(%w[CANCELLED COMPLETED]) # kept, then built after all
      expect(app_job["start_time"]).to be >= jobs.last["end_time"]
      cut!("publish")
      expect(@cutoff.published).to include(@cutoff.source("base/user") => user["version"], @cutoff.source("base/app") => app["version"])
    end

    it "builds the candidates with --rebuild-dependents" do
      change("cut.c", "#include \"cut.h\"\nint cut_value(void) { return 47; }\n")
      cut!("compile")
      slurm_build("--rebuild-dependents")
      expect(cutoff_record("base/user")).to include("status" => "built")
      expect(cutoff_record("base/user")["cutoff"])
        .to include("verdict" => "rebuild", "reason" => "--rebuild-dependents: every candidate is built")
      cut!("publish")
    end

    it "rebuilds the dependent of a header change, naming the library" do
      before = cutoff_record("base/lib")
      change("cut.h", "int cut_value(void);\nint cut_other(void);\n")
      cut!("compile")
      slurm_build
      expect(cutoff_record("base/lib")["interface"]).to include("against" => before["version"], "verdict" => "changed",
                                                                "changes" => ["opt/rock/sc/rock-sc-base-lib/include/cut.h: differs"])
      expect(cutoff_record("base/user")).to include("status" => "built")
      expect(cutoff_record("base/user")["cutoff"]).to include("verdict" => "rebuild",
                                                              "reason" => "the interface of #{@cutoff.source('base/lib')} changed")
    end
  end

  it "builds a real sbuild chain through Slurm, the chroot made by the target's chroot job" do
    release = BuildRelease.new(File.join(@dir, "sbuild"), "sls")
    release.package("base/one")
    release.package("base/two", dependencies: ["base/one"])
    release.compile
    # the chroot tarballs of the test run (made by the first sbuild test, or here by the chroot job)
    shared = File.join(CliRunner::CACHE, "relspec")
    run = @cluster.relspec("build", "specs/sls.yml", "--out", "out", "--backend", "sbuild", "--engine", "slurm",
                           "--slurm", "poll_interval=0.5", "--slurm", "shared_folder=#{shared}", chdir: release.dir,
                                                                                                 env: @cluster.with_network(%w[sbuild mmdebstrap]))
    expect(run.exit_code).to eq(0), run.stdout + run.stderr
    packages = results(release).fetch("packages")
    expect(results(release).fetch("backend")).to eq("sbuild")
    expect(packages.values.map { |record| record["status"] }).to eq(%w[built built])
    expect(File.size(File.join(shared, "chroots", "bookworm-amd64.tar.zst"))).to be > 10_000_000
    script = File.read(Dir.glob(File.join(release.target_dir, "slurm", "*", "#{release.source('base/two')}.sh")).first)
    # the sbuild backend's own command line, given the first package's results folder
    expect(script).to include("sbuild --chroot-mode=unshare --chroot=#{shared}/chroots/bookworm-amd64.tar.zst",
                              "--extra-package=#{release.target_dir}/results/#{release.source('base/one')}")
    two = File.read(File.join(release.target_dir, "logs", "#{release.source('base/two')}.log"))
    # sbuild installed the build-dependency the job before built.
    expect(two).to match(/Unpacking #{Regexp.escape(release.source('base/one'))} /)
    expect(File.read(File.join(release.target_dir, "logs", "prepare.log"))).to include("$ if [ ! -f ")
  end
end
