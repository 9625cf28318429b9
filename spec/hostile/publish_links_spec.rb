# frozen_string_literal: true

require "spec_helper"
require_relative "../support/build_release"

# `relspec publish` over links it did not make (issue 46, cases 2, 3 and
# 4): a build's logs/ that leads out of the output tree, a repository whose
# report/logs or abi/<target>/<source> is a link to a folder of the user's.
# One real release, built once with the host backend: a package that
# installs an oroGen type registry, so that its build keeps an ABI dump
# (no abidiff needed) and publish writes it beside the repository. Each
# link is refused, naming it, before the repository is touched: nothing
# is published, nothing outside is read, written or deleted.
RSpec.describe "relspec publish over links it did not make", order: :defined do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-publish-links")
    @release = BuildRelease.new(@dir, "ln")
    @release.package("test/typekit", cmake: "install(FILES std.tlb DESTINATION share/orogen)",
                                     files: { "std.tlb" => File.read(File.expand_path("../fixtures/abi/std.tlb", __dir__)) })
    @release.compile(spec: "repository: { path: ../repos/ln, trusted: true }\n")
    run = relspec("build", "specs/ln.yml", "--out", "out", "--backend", "host", chdir: @dir)
    raise "relspec build: #{run.stdout}#{run.stderr}" unless run.status.success?
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  around do |example|
    FileUtils.mkdir_p(outside)
    File.write(File.join(outside, "precious.txt"), "mine\n")
    example.run
  ensure
    FileUtils.rm_rf([outside, repository])
  end

  let(:repository) { File.join(@dir, "repos", "ln") }
  let(:outside) { File.join(@dir, "outside") }
  let(:source) { @release.source("test/typekit") }
  let(:dump) { "std.tlb.abi.xml.gz" }

  def publish
    relspec("publish", "specs/ln.yml", "--out", "out", chdir: @dir)
  end

  # The repository holds nothing but what the test put there.
  def expect_nothing_published
    %w[conf db dists pool osdeps].each { |name| expect(File.exist?(File.join(repository, name))).to be(false), name }
  end

  it "publishes the release, its page, its logs and its dump when nothing is a link, and again" do
    2.times do
      run = publish
      expect(run.exit_code).to eq(0), run.stderr
    end
    expect(File.file?(File.join(repository, "report", "logs", "bookworm-amd64", "#{source}.log"))).to be(true)
    expect(File.file?(File.join(repository, "abi", "bookworm-amd64", source, dump))).to be(true)
  end

  it "case 2: refuses a build's logs/ that is a link out of the output tree, and publishes nothing of it" do
    logs = File.join(@release.target_dir, "logs")
    FileUtils.mv(logs, File.join(outside, "logs"))
    File.symlink(File.join(outside, "logs"), logs)
    run = publish
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: out/ln/bookworm-amd64/logs is a symbolic link (to #{outside}/logs): the " \
                             "report reads a build's logs only inside out/ln/bookworm-amd64, never through a link; " \
                             "remove the link and build again\n")
    expect(File.exist?(repository)).to be(false)
  ensure
    File.delete(logs) if File.symlink?(logs)
    FileUtils.mv(File.join(outside, "logs"), logs) if File.directory?(File.join(outside, "logs"))
  end

  it "case 3: refuses a report/logs of the repository that is a link, and deletes nothing of its folder" do
    FileUtils.mkdir_p(File.join(repository, "report"))
    File.symlink(outside, File.join(repository, "report", "logs"))
    run = publish
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: #{repository}/report/logs is a symbolic link (to #{outside}): relspec " \
                             "writes the report only inside #{repository}/report and never through a link (its " \
                             "clean-up would delete the files the link leads to); remove the link and run again\n")
    expect(Dir.children(outside)).to eq(["precious.txt"])
    expect(File.read(File.join(outside, "precious.txt"))).to eq("mine\n")
    expect_nothing_published
  end

  it "case 4: refuses an abi/<target>/<source> of the repository that is a link, and overwrites nothing of its folder" do
    File.write(File.join(outside, dump), "the user's own file\n")
    FileUtils.mkdir_p(File.join(repository, "abi", "bookworm-amd64"))
    File.symlink(outside, File.join(repository, "abi", "bookworm-amd64", source))
    run = publish
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: #{repository}/abi/bookworm-amd64/#{source} is a symbolic link (to " \
                             "#{outside}): publish writes the ABI dumps only inside #{repository}/abi/bookworm-amd64 " \
                             "and never through a link; remove the link and publish again\n")
    expect(Dir.children(outside).sort).to eq(["precious.txt", dump])
    expect(File.read(File.join(outside, dump))).to eq("the user's own file\n")
    expect_nothing_published
  end

  it "refuses an osdeps/ of the repository that is a link, and overwrites nothing of its folder" do
    File.write(File.join(outside, "ln-amd64.yml"), "the user's own file\n")
    FileUtils.mkdir_p(repository)
    File.symlink(outside, File.join(repository, "osdeps"))
    run = publish
    expect([run.exit_code, run.stdout]).to eq([1, ""])
    expect(run.stderr).to eq("relspec: error: #{repository}/osdeps is a symbolic link (to #{outside}): publish writes " \
                             "its osdeps files only inside #{repository} and never through a link; remove the link " \
                             "and publish again\n")
    expect(File.read(File.join(outside, "ln-amd64.yml"))).to eq("the user's own file\n")
    expect(Dir.children(repository)).to eq(["osdeps"])
  end
end
