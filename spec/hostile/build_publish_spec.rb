# frozen_string_literal: true

require "spec_helper"
require "yaml"
require "digest"
require "time"
require_relative "../support/build_release"

# Concurrency and faults of build and publish (issue 24, item 4), with real
# processes, real builds (host backend) and a real reprepro. The guarantees
# are those of docs/limits.md ("Concurrent runs and faults"):
#
# - one build of a target at a time: a second `relspec build` of it, or a
#   `relspec publish` of it, refuses at once naming the running build;
# - a publish that fails on a full disk (a real tmpfs, mounted here: the
#   tests run as root) or is killed at any reprepro step leaves a
#   consistent repository (`reprepro check` and `checkpool` clean, every
#   file a Release lists with its SHA256 and size), and a re-run completes.
#
# One release, compiled and built once, serves every example (in order).
RSpec.describe "relspec build and publish under concurrency and faults", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-concurrency")
    @release = BuildRelease.new(@dir, "conc")
    @release.package("base/a1")
    # Last in the plan and slow: the first build still runs when the
    # second one and the publish start.
    @release.package("base/zslow", cmake: "execute_process(COMMAND sleep 4)")
    @release.compile(spec: "repository: { path: ../repos/conc, trusted: true }\n")
    @repos = File.join(@dir, "repos")
    FileUtils.mkdir_p(@repos)
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  let(:repository) { File.join(@repos, "conc") }
  let(:spec) { "specs/conc.yml" }

  def wait_for(what, seconds: 120)
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + seconds
    until yield
      raise "#{what} did not happen within #{seconds} s" if Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline

      sleep(0.05)
    end
  end

  # Runs relspec without the memory report (a killed child has none);
  # [status, stderr].
  def spawned(*args, env: {})
    run = finish_relspec(spawn_relspec(*args, chdir: @dir, env: env))
    [run.status, run.stderr]
  end

  def reprepro(*args)
    Open3.capture2e("reprepro", "--basedir", repository, *args)
  end

  # The repository is what reprepro and apt expect: its database agrees
  # with the pool, and every file a Release lists has the bytes listed.
  def expect_consistent
    return unless File.directory?(File.join(repository, "db"))

    %w[check checkpool].each do |command|
      output, status = reprepro(command)
      expect(status).to be_success, "reprepro #{command}: #{output}"
    end
    expect_dists_consistent
  end

  # What apt clients read is whole: every file a Release lists has the
  # bytes listed.
  def expect_dists_consistent
    Dir.glob(File.join(repository, "dists", "*", "Release")).each do |release|
      listed = File.read(release)[/^SHA256:\n((?: .*\n)*)/, 1].to_s.lines.map(&:split)
      expect(listed).not_to be_empty
      listed.each do |sha256, size, name|
        file = File.join(File.dirname(release), name)
        next unless File.exist?(file) # reprepro lists uncompressed indices it does not keep

        expect([Digest::SHA256.file(file).hexdigest, File.size(file).to_s]).to eq([sha256, size]), "#{release}: #{name}"
      end
    end
  end

  def expect_published
    output, status = reprepro("--list-format", "${package}\n", "list", "bookworm")
    expect(status).to be_success, output
    expect(output.lines.map(&:chomp).uniq.sort).to eq([@release.source("base/a1"), @release.source("base/zslow")])
  end

  # A publish after a fault: it runs to its end and leaves everything
  # published in a consistent repository.
  def expect_publish_completes
    status, message = spawned("publish", spec, "--out", "out")
    expect(status.exitstatus).to eq(0), message
    expect_consistent
    expect_published
  end

  # Issue 46, case 16: the refusal says since when the holder runs.
  it "refuses a second build and a publish of a target while a build of it runs, naming the build and since when" do
    started = Time.now.utc - 3 # /proc says the boot time in whole seconds, the message too
    pid = spawn_relspec("build", spec, "--out", "out", "--backend", "host", chdir: @dir)
    slow_log = File.join(@release.target_dir, "logs", "#{@release.source('base/zslow')}.log")
    wait_for("the first build reaching base/zslow") { File.exist?(slow_log) }
    holder = Regexp.escape("out/conc/bookworm-amd64: relspec build (pid #{pid}, since ")
    finished = Regexp.escape(" UTC) is using it; run again when it has finished")
    busy = /\Arelspec: error: cannot (build|publish) #{holder}(\d{4}-\d\d-\d\d \d\d:\d\d:\d\d)#{finished}\n\z/

    second = relspec("build", spec, "--out", "out", "--backend", "host", chdir: @dir)
    publish = relspec("publish", spec, "--out", "out", chdir: @dir)
    expect([second.exit_code, publish.exit_code]).to eq([1, 1])
    expect([second.stderr[busy, 1], publish.stderr[busy, 1]]).to eq(%w[build publish]), "#{second.stderr}#{publish.stderr}"
    since = Time.strptime("#{publish.stderr[busy, 2]} UTC", "%Y-%m-%d %H:%M:%S %Z")
    expect(since).to be_between(started, Time.now.utc)
    expect(File.exist?(repository)).to be(false) # refused before touching the repository

    expect(finish_relspec(pid).status).to be_success
    statuses = YAML.safe_load(File.read(File.join(@release.target_dir, "build-results.yml")))["packages"].values
    expect(statuses.map { |package| package["status"] }).to eq(%w[built built])
  end

  # The cases that were exit 70 (files: an integer, null or a list of
  # lists), for build (resume) and publish, and a damaged plan.yml: refused
  # at the line, nothing built or published, the files left as they were.
  it "refuses a damaged build-results.yml in build and publish, and a damaged plan.yml in build, at the line" do
    results = File.join(@release.target_dir, "build-results.yml")
    plan = File.join(@release.target_dir, "plan.yml")
    pristine = File.read(results)
    text = File.read(plan)
    first_files = /^    files:\n(    [- ] .*\n)+/ # the first package's (rock-conc-base-a1) list
    line = pristine.lines.index("    files:\n") + 1
    {
      "    files: 7\n" => [line, "packages.#{@release.source('base/a1')}.files must be a list of files"],
      "    files:\n" => [line, "a built package lists the files it produced"],
      "    files:\n    - [a, b]\n" => [line + 1, "packages.#{@release.source('base/a1')}.files.0 must be a mapping of name, sha256 and size"]
    }.each do |damage, (at, message)|
      damaged = pristine.sub(first_files, damage)
      expect(damaged).not_to eq(pristine)
      File.write(results, damaged)
      %w[build publish].each do |command|
        run = relspec(command, spec, "--out", "out", *(command == "build" ? %w[--backend host] : []), chdir: @dir)
        expect([run.exit_code, run.stdout]).to eq([1, ""]), run.stderr
        expect(run.stderr).to start_with("out/conc/bookworm-amd64/build-results.yml:#{at}:")
          .and(include("error[build-results]: cannot read the build results: #{message}"))
      end
      expect(File.exist?(repository)).to be(false)
    end
    File.write(results, pristine)
    File.write(plan, text.sub(/dsc: \S+/, "dsc: /etc/passwd"))
    run = relspec("build", spec, "--out", "out", "--backend", "host", chdir: @dir)
    expect([run.exit_code, run.stderr]).to match([1, %r{\Aout/conc/bookworm-amd64/plan.yml:\d+:\d+: error\[build-plan\]: cannot read the build plan: builds\.0\.dsc "/etc/passwd" is not a plain path}])
    expect(File.read(results)).to eq(pristine)
    # an early cutoff candidate whose kept build was made against no Debian version (issue 45)
    against = "  build_depends: []\n  cutoff:\n    keeps: 1-1\n    because: []\n    against:\n      rock-x: 2 0\n"
    File.write(plan, text.sub("  build_depends: []\n", against))
    line = text.lines.index("  build_depends: []\n") + 6
    run = relspec("build", spec, "--out", "out", "--backend", "host", chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""]), run.stderr
    expect(run.stderr).to start_with("out/conc/bookworm-amd64/plan.yml:#{line}:")
      .and(include('error[build-plan]: cannot read the build plan: invalid Debian version "2 0"'))
    expect(run.stderr).not_to include("from /")
    expect(File.read(results)).to eq(pristine)
  ensure
    File.write(results, pristine)
    File.write(plan, text)
  end

  # Publish lists the repository's osdeps from the release's lock: without
  # it, or with the lock of another spec, it refuses before touching the
  # repository instead of listing decisions nobody made.
  it "refuses to publish without the release's lock, or with the lock of another spec, naming the lock" do
    lock = File.join(@dir, "releases", "conc", "lock.yml")
    spec_file = File.join(@dir, spec)
    pristine_lock = File.read(lock)
    pristine_spec = File.read(spec_file)
    hint = "hint: run relspec compile #{spec} (and build) again, then publish"

    File.delete(lock)
    run = relspec("publish", spec, "--out", "out", chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to include("releases/conc/lock.yml: error[publish-lock]: conc has no lock releases/conc/lock.yml " \
                                  "to list its repository from", hint)
    File.write(lock, pristine_lock)

    File.write(spec_file, pristine_spec.sub("Demo <demo@example.org>", "Other <other@example.org>"))
    run = relspec("publish", spec, "--out", "out", chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to include("error[publish-lock]: releases/conc/lock.yml was planned from another version of #{spec}", hint)
    expect(run.stderr).not_to include("Traceback", ".rb:")
    File.write(spec_file, pristine_spec)

    # a damaged lock: the hint names compile's --discard-lock, which publish does not have
    File.write(lock, "relspec_lock: [\n")
    run = relspec("publish", spec, "--out", "out", chdir: @dir)
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to start_with("releases/conc/lock.yml:")
    expect(run.stderr).to include("error[lock]", "hint: fix the file (it is in git), or run relspec compile #{spec} " \
                                                 "--discard-lock (and build) again, then publish")
    expect(File.read(lock)).to eq("relspec_lock: [\n")
    expect(File.exist?(repository)).to be(false)
  ensure
    File.write(lock, pristine_lock)
    File.write(spec_file, pristine_spec)
  end

  it "keeps the repository consistent when the disk fills during publish, and completes once there is space" do
    system("mount", "-t", "tmpfs", "-o", "size=1m", "relspec-full", @repos, exception: true)
    begin
      filler = File.join(@repos, "filler")
      failures = [4096, 64 * 1024].map do |free|
        FileUtils.rm_rf(repository)
        File.open(filler, "wb") do |file|
          loop { file.write("\0" * 65_536) }
        rescue Errno::ENOSPC
          file.truncate([file.size - free, 0].max)
        end
        status, failure = spawned("publish", spec, "--out", "out")
        expect(status.exitstatus).to eq(1), failure
        expect(failure).to start_with("relspec: error: ").and(include("No space left on device"))
        File.delete(filler)
        expect_consistent
        expect_publish_completes
        failure
      end
      # at least one of the fills stopped reprepro itself, not only relspec's own writes
      expect(failures.join).to include("reprepro")
    ensure
      system("umount", @repos)
    end
  end

  # What a reprepro killed while holding its lock leaves (the fault below
  # leaves it when the kill comes late enough): publish removes it, since
  # no reprepro uses the repository, says so, and completes.
  it "removes reprepro's stale lock file left by a killed reprepro, says so, and publishes" do
    expect_publish_completes
    lock = File.join(repository, "db", "lockfile")
    File.write(lock, "")
    status, message = spawned("publish", spec, "--out", "out")
    expect(status.exitstatus).to eq(0), message
    expect(message).to include("removed reprepro's stale lock #{lock} (no reprepro uses the repository")
    expect(File.exist?(lock)).to be(false)
    expect_consistent
    expect_published
  end

  # A fault-injecting wrapper around reprepro (first in PATH): its k-th call
  # starts the real reprepro, then kills it and relspec with SIGKILL, for
  # every k until a publish runs to its end. reprepro works on relspec's
  # copy (Publish::Transaction), so a kill before the switch leaves the
  # live conf/, db/ and dists/ as they were (but for reprepro's lock,
  # which the next publish removes), whatever reprepro was doing to the
  # copy; the next publish drops the copy and completes.
  it "keeps the repository consistent when publish is killed at any reprepro step, and a re-run completes" do
    FileUtils.rm_rf(repository)
    bin = File.join(@dir, "killer-bin")
    FileUtils.mkdir_p(bin)
    File.write(File.join(bin, "reprepro"), <<~SH)
      #!/bin/sh
      count=$(( $(cat "$KILL_COUNTER" 2>/dev/null || echo 0) + 1 ))
      echo "$count" > "$KILL_COUNTER"
      [ "$count" = "$KILL_AT" ] || exec /usr/bin/reprepro "$@"
      /usr/bin/reprepro "$@" & sleep 0.05; kill -9 $! $PPID
    SH
    File.chmod(0o755, File.join(bin, "reprepro"))
    counter = File.join(@dir, "reprepro-calls")
    work = File.join(repository, ".relspec-publish-work")
    left_work = false
    killed = (1..20).take_while do |k|
      File.write(counter, "0")
      before = live_state
      status, message = spawned("publish", spec, "--out", "out",
                                env: { "PATH" => "#{bin}:#{ENV.fetch('PATH')}", "KILL_AT" => k.to_s, "KILL_COUNTER" => counter })
      expect_dists_consistent
      if File.read(counter).to_i < k # ran to its end before the k-th call
        expect(status.exitstatus).to eq(0), message
        expect(message.include?("was interrupted and had not started to change it")).to eq(left_work), message
        next false
      end

      expect(status.termsig).to eq(9), message
      left_work = File.exist?(work)
      expect(live_state).to eq(before) if left_work # killed before the switch
      true
    end
    expect(killed.size).to be >= 3
    expect_consistent
    expect_published
    expect(Dir.children(repository)).not_to include(".relspec-publish-work")
  end

  # The live conf/, db/ and dists/ with their bytes (reprepro's lock left out).
  def live_state
    %w[conf db dists].flat_map { |name| Dir.glob("#{name}/**/*", base: repository) }.sort.to_h do |path|
      file = File.join(repository, path)
      [path, File.file?(file) ? Digest::SHA256.file(file).hexdigest : :dir]
    end.except("db/lockfile")
  end

  # Publish as a transaction (issue 34, cases 1-4), on the repository the
  # examples above left published: a refused or killed publish leaves the
  # live repository byte for byte as it was, a package included by hand
  # with reprepro between two publishes is never rolled back, the copy an
  # interrupted publish left is never put in place of an intact database,
  # and reprepro's lock is never taken from a reprepro that reaches the
  # repository through another path (a bind mount; the tests run as root).
  # A binary package made by hand, as a maintainer includes one.
  def hand_deb(name)
    root = File.join(@dir, name)
    FileUtils.mkdir_p(File.join(root, "DEBIAN"))
    File.write(File.join(root, "DEBIAN", "control"),
               "Package: #{name}\nVersion: 1.0\nArchitecture: all\nSection: misc\nPriority: optional\n" \
               "Maintainer: Demo <demo@example.org>\nDescription: included by hand\n")
    deb = File.join(@dir, "#{name}_1.0_all.deb")
    return deb if File.exist?(deb)

    output, status = Open3.capture2e("dpkg-deb", "--root-owner-group", "--build", root, deb)
    raise output unless status.success?

    deb
  end

  def listed
    output, status = reprepro("--list-format", "${package}\n", "list", "bookworm")
    expect(status).to be_success, output
    output.lines.map(&:chomp).uniq.sort
  end

  def include_by_hand(deb = hand_deb("hand-made"))
    output, status = reprepro("includedeb", "bookworm", deb)
    expect(status).to be_success, output
  end

  # Every file of the live repository (conf, db, dists, pool, osdeps) with
  # its bytes; relspec's own lock and work folder left out.
  def live_tree
    Dir.glob("**/*", File::FNM_DOTMATCH, base: repository).reject { |path| path.end_with?(".") }
       .grep_v(/\A\.relspec-publish-(lock|work)/).sort.to_h do |path|
      file = File.join(repository, path)
      [path, File.file?(file) ? Digest::SHA256.file(file).hexdigest : File.ftype(file)]
    end
  end

  def publish
    relspec("publish", spec, "--out", "out", chdir: @dir)
  end

  def expect_published_with(run, by_hand: ["hand-made"])
    expect([run.exit_code, run.stderr]).to match([0, anything]), run.stderr
    expect(listed).to eq([@release.source("base/a1"), @release.source("base/zslow"), *by_hand].sort)
    expect(Dir.children(repository)).not_to include(".relspec-publish-work")
    output, status = reprepro("check")
    expect(status).to be_success, output
  end

  # Same version, other bytes: the built .deb and its record changed so
  # that the results are consistent but the pool holds the name with
  # other bytes. Yields, then puts the build back.
  def with_rebuilt_deb
    results = File.join(@release.target_dir, "build-results.yml")
    deb = Dir.glob(File.join(@release.target_dir, "**", "#{@release.source('base/a1')}_*.deb")).first
    pristine = [File.read(results), File.binread(deb)]
    old_sha = Digest::SHA256.file(deb).hexdigest
    File.binwrite(deb, "#{pristine[1]}\0")
    File.write(results, pristine[0].sub(old_sha, Digest::SHA256.file(deb).hexdigest)
                                   .sub(/(sha256: #{Digest::SHA256.file(deb).hexdigest}\n\s+size: )\d+/) { "#{Regexp.last_match(1)}#{File.size(deb)}" })
    yield deb
  ensure
    File.write(results, pristine[0])
    File.binwrite(deb, pristine[1])
  end

  it "case 1: leaves the repository byte-identical when it refuses, and keeps a package included by hand" do
    include_by_hand
    before = live_tree
    with_rebuilt_deb do |deb|
      run = publish
      expect([run.exit_code, run.stdout]).to eq([1, ""])
      expect(run.stderr).to start_with("relspec: error: refusing to publish a file whose name the repository already " \
                                       "holds with other bytes").and(include(deb.delete_prefix("#{@dir}/")))
      expect(run.stderr).not_to include("Traceback", ".rb:")
    end
    expect(live_tree).to eq(before)
    expect(Dir.children(repository)).not_to include(".relspec-publish-work", ".relspec-publish-unfinished")
    run = publish
    expect_published_with(run)
    expect(run.stderr).not_to include("interrupted")
  end

  it "case 2: leaves the repository byte-identical when killed while copying, and the next publish keeps the hand-made package" do
    with_rebuilt_deb { expect(publish.exit_code).to eq(1) } # a refusal first, as in the issue
    include_by_hand(hand_deb("hand-late"))
    before = live_tree
    pid = spawn_relspec("publish", spec, "--out", "out", chdir: @dir)
    work = File.join(repository, ".relspec-publish-work")
    old_copy = File.join(repository, ".relspec-db-before-publish") # what relspec before the fix copied to
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep(0.005) until File.exist?(work) || File.exist?(old_copy) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    signal_relspec(pid, "KILL")
    expect(finish_relspec(pid).status.termsig).to eq(9)
    # what a killed reprepro leaves too: reprepro's lock, removed by the next publish
    expect(live_tree.except("db/lockfile")).to eq(before)
    run = publish
    expect_published_with(run, by_hand: %w[hand-made hand-late])
    expect(run.stderr).to include("the last publish into #{repository} was interrupted and had not started to change it")
  end

  it "case 3: never puts an interrupted publish's damaged copy in place of the intact database, and says what to do" do
    before = live_tree
    # what a publish of relspec before the fix left: its marker and a damaged copy
    marker = File.join(repository, ".relspec-publish-unfinished")
    copy = File.join(repository, ".relspec-db-before-publish")
    FileUtils.mkdir_p(copy)
    File.write(File.join(copy, "packages.db"), "not a Berkeley DB file\n" * 100)
    File.write(marker, "")
    run = publish
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to start_with("relspec: error: #{marker}: a publish by an earlier relspec was interrupted here")
      .and(include("If `reprepro -b #{repository} check` succeeds, #{repository}/db is whole: remove #{marker} and #{copy}"))
    expect(run.stderr.lines.size).to eq(1)
    expect(live_tree.reject { |path, _| path.start_with?(".relspec-db-before-publish", ".relspec-publish-unfinished") })
      .to eq(before)
    FileUtils.rm_rf([marker, copy])

    # a ready copy of this relspec's that does not match (damaged since): not used
    work = File.join(repository, ".relspec-publish-work")
    %w[conf dists db].each { |name| FileUtils.mkdir_p(File.join(work, name)) }
    File.write(File.join(work, "db", "packages.db"), "not a Berkeley DB file\n" * 100)
    File.write(File.join(work, "READY"), "#{'0' * 64} #{'1' * 64}\n")
    run = publish
    expect(run.stderr).to include("the last publish into #{repository} was interrupted and left a new state that no " \
                                  "longer matches the repository")
    expect_published_with(run, by_hand: %w[hand-made hand-late])
  end

  it "case 4: waits for a reprepro that holds the lock through a bind mount instead of removing its lock" do
    bound = File.join(@dir, "bound")
    FileUtils.mkdir_p(bound)
    system("mount", "--bind", repository, bound, exception: true)
    begin
      # an export hook that sleeps: reprepro holds its lock meanwhile
      started = File.join(@dir, "hook-started")
      hook = File.join(@dir, "slow-hook")
      File.write(hook, "#!/bin/sh\ntouch #{started}\nsleep 2\n")
      File.chmod(0o755, hook)
      conf = File.join(repository, "conf", "distributions")
      pristine = File.read(conf)
      File.write(conf, pristine.sub("Components: main\n", "Components: main\nDebIndices: Packages Release . .gz #{hook}\n"))
      output = nil
      hand = Thread.new { output = Open3.capture2e("reprepro", "-b", bound, "export", "bookworm", chdir: "/") }
      deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 30
      sleep(0.02) until File.exist?(started) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
      expect(File.exist?(File.join(repository, "db", "lockfile"))).to be(true)
      run = publish
      hand.join
      text, status = output
      expect([status.success?, text]).to match([true, anything]), text
      expect(text).not_to include("deleting lock file")
      expect(run.stderr).to include("waiting for the reprepro holding #{repository}/db/lockfile to finish…")
      expect(run.stderr).not_to include("removed reprepro's stale lock")
      expect_published_with(run, by_hand: %w[hand-made hand-late])
    ensure
      system("umount", bound)
    end
  end

  # Issue 34, case 5: the same built release, built again with a log file
  # or the results folder made a link to outside the project.
  it "case 5: refuses to build through a link out of the target folder, naming it, and touches nothing outside" do
    outside = File.join(Dir.mktmpdir("relspec-outside"), "keep")
    FileUtils.mkdir_p(outside)
    File.write(File.join(outside, "precious.txt"), "mine\n")
    log = File.join(@release.target_dir, "logs", "#{@release.source('base/a1')}.log")
    results = File.join(@release.target_dir, "results")
    pristine = File.read(log)
    {
      log => File.join(outside, "precious.txt"),
      results => outside
    }.each do |link, to|
      File.rename(link, "#{link}.real")
      File.symlink(to, link)
      begin
        run = relspec("build", spec, "--out", "out", "--backend", "host", "--rebuild", chdir: @dir)
        expect([run.exit_code, run.stdout]).to eq([1, ""])
        expect(run.stderr).to eq("relspec: error: #{link} is a symbolic link (to #{to}): a build writes only inside " \
                                 "#{@release.target_dir} and never through a link; remove the link and build again\n")
        expect(Dir.children(outside)).to eq(["precious.txt"])
        expect(File.read(File.join(outside, "precious.txt"))).to eq("mine\n")
      ensure
        File.delete(link)
        File.rename("#{link}.real", link)
      end
    end
    expect(File.read(log)).to eq(pristine)
  ensure
    FileUtils.rm_rf(File.dirname(outside))
  end
  # Issue 46, case 15: an empty folder of another user was given to the
  # build user (chown to the subordinate uid, mode 0700) without a word.
  it "case 6: refuses a ccache or apt download cache folder that is relative, a link or someone else's (empty or not), before any build" do
    outside = Dir.mktmpdir("relspec-outside")
    File.write(File.join(outside, "precious.o"), "mine\n")
    link = File.join(@dir, "cache-link")
    File.symlink(outside, link)
    foreign = Dir.mktmpdir("relspec-foreign") # empty, another user's
    File.chmod(0o755, foreign)
    File.chown(4242, 4242, foreign)
    build_uid = File.read("/etc/subuid")[/^root:(\d+):/, 1]
    { "RELSPEC_CCACHE" => "ccache", "RELSPEC_APT_CACHE" => "apt download cache" }.each do |variable, what|
      {
        "cache" => "#{variable}=cache: not an absolute folder (or \"off\")",
        link => "#{what} folder #{link} is not a folder (#{variable} chooses another, \"off\" none)",
        outside => "#{what} folder #{outside} belongs to uid #{Process.uid}, not to the uid sbuild's build user has " \
                   "here (#{build_uid}): chown -R ",
        foreign => "#{what} folder #{foreign} belongs to uid 4242, not to the uid sbuild's build user has here " \
                   "(#{build_uid}): chown -R "
      }.each do |folder, message|
        run = relspec("build", spec, "--out", "out", "--backend", "sbuild", "--rebuild", chdir: @dir,
                                                                                         env: { variable => folder })
        expect([run.exit_code, run.stdout]).to eq([1, ""])
        expect(run.stderr).to start_with("relspec: error: #{message}")
      end
    end
    expect([Dir.children(outside), File.stat(outside).uid]).to eq([["precious.o"], Process.uid])
    expect([Dir.children(foreign), File.stat(foreign).uid, File.stat(foreign).mode & 0o777]).to eq([[], 4242, 0o755])
  ensure
    FileUtils.rm_rf(outside)
    FileUtils.rm_rf(foreign) if foreign
  end

  # Issue 48: the budget of the kept build-dependency layers is a size;
  # anything else stops the run before the backend builds anything.
  it "case 7: refuses a RELSPEC_LAYER_BUDGET that is no size, before any build" do
    results = File.join(@release.target_dir, "build-results.yml")
    before = File.exist?(results) ? File.read(results) : nil
    ["", "lots", "1.5G", "-1"].each do |value|
      run = relspec("build", spec, "--out", "out", "--backend", "sbuild", "--rebuild", chdir: @dir,
                                                                                       env: { "RELSPEC_LAYER_BUDGET" => value })
      expect([run.exit_code, run.stdout]).to eq([1, ""])
      expect(run.stderr).to eq("relspec: error: RELSPEC_LAYER_BUDGET=#{value.inspect}: not a size (bytes, or a number with K, M or G)\n")
    end
    expect(File.exist?(results) ? File.read(results) : nil).to eq(before)
  end
end
