# frozen_string_literal: true

require "spec_helper"
require "digest"
require "open3"
require "yaml"
require_relative "../support/build_release"

# Publish as a transaction (issue 34, cases 1-4), with a real reprepro and a
# real build (host backend): a refused or killed publish leaves the live
# repository byte for byte as it was, a package included by hand with
# reprepro between two publishes is never rolled back, the copy an
# interrupted publish left is never put in place of an intact database,
# and reprepro's lock is never taken from a reprepro that reaches the
# repository through another path (a bind mount; the tests run as root).
# One release, built once, serves every example (in order).
RSpec.describe "relspec publish as a transaction", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-transaction")
    @release = BuildRelease.new(@dir, "tx")
    @release.package("base/a1")
    @release.compile(spec: "repository: { path: ../repos/tx, trusted: true }\n")
    build = relspec("build", "specs/tx.yml", "--out", "out", "--backend", "host", chdir: @dir)
    raise "relspec build failed: #{build.stderr}" unless build.exit_code.zero?

    @hand = hand_deb("hand-made")
    @late = hand_deb("hand-late")
    publish = relspec("publish", "specs/tx.yml", "--out", "out", chdir: @dir)
    raise "relspec publish failed: #{publish.stderr}" unless publish.exit_code.zero?
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  let(:repository) { File.join(@dir, "repos", "tx") }

  # A binary package made by hand, as a maintainer includes one.
  def hand_deb(name)
    root = File.join(@dir, name)
    FileUtils.mkdir_p(File.join(root, "DEBIAN"))
    File.write(File.join(root, "DEBIAN", "control"),
               "Package: #{name}\nVersion: 1.0\nArchitecture: all\nSection: misc\nPriority: optional\n" \
               "Maintainer: Demo <demo@example.org>\nDescription: included by hand\n")
    deb = File.join(@dir, "#{name}_1.0_all.deb")
    output, status = Open3.capture2e("dpkg-deb", "--root-owner-group", "--build", root, deb)
    raise output unless status.success?

    deb
  end

  def reprepro(*args, base: repository)
    Open3.capture2e("reprepro", "--basedir", base, *args)
  end

  def listed
    output, status = reprepro("--list-format", "${package}\n", "list", "bookworm")
    expect(status).to be_success, output
    output.lines.map(&:chomp).uniq.sort
  end

  def include_by_hand(deb = @hand)
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
    relspec("publish", "specs/tx.yml", "--out", "out", chdir: @dir)
  end

  def expect_published(run, by_hand: ["hand-made"])
    expect([run.exit_code, run.stderr]).to match([0, anything]), run.stderr
    expect(listed).to eq([@release.source("base/a1"), *by_hand].sort)
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
    expect_published(run)
    expect(run.stderr).not_to include("interrupted")
  end

  it "case 2: leaves the repository byte-identical when killed while copying, and the next publish keeps the hand-made package" do
    with_rebuilt_deb { expect(publish.exit_code).to eq(1) } # a refusal first, as in the issue
    include_by_hand(@late)
    before = live_tree
    pid = spawn_relspec("publish", "specs/tx.yml", "--out", "out", chdir: @dir)
    work = File.join(repository, ".relspec-publish-work")
    old_copy = File.join(repository, ".relspec-db-before-publish") # what relspec before the fix copied to
    deadline = Process.clock_gettime(Process::CLOCK_MONOTONIC) + 60
    sleep(0.005) until File.exist?(work) || File.exist?(old_copy) || Process.clock_gettime(Process::CLOCK_MONOTONIC) > deadline
    signal_relspec(pid, "KILL")
    expect(finish_relspec(pid).status.termsig).to eq(9)
    # what a killed reprepro leaves too: reprepro's lock, removed by the next publish
    expect(live_tree.except("db/lockfile")).to eq(before)
    run = publish
    expect_published(run, by_hand: %w[hand-made hand-late])
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
    expect_published(run, by_hand: %w[hand-made hand-late])
  end

  it "case 4: waits for a reprepro that holds the lock through a bind mount instead of removing its lock" do
    bound = File.join(@dir, "bound")
    FileUtils.mkdir_p(bound)
    system("mount", "--bind", repository, bound, exception: true)
    begin
      # an export hook that sleeps: reprepro holds its lock meanwhile
      started = File.join(@dir, "hook-started")
      hook = File.join(@dir, "slow-hook")
      File.write(hook, "#!/bin/sh\ntouch #{started}\nsleep 3\n")
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
      expect_published(run, by_hand: %w[hand-made hand-late])
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
        run = relspec("build", "specs/tx.yml", "--out", "out", "--backend", "host", "--rebuild", chdir: @dir)
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
end
