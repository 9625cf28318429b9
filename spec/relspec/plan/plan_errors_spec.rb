# frozen_string_literal: true

require "spec_helper"

# Broken ancestor repositories, through the real CLI: one message naming the
# ancestor and the URL, exit 1, no backtrace, and no lock written.
RSpec.describe "relspec plan with broken ancestor repositories" do
  before(:all) do
    @dir = Dir.mktmpdir("relspec-plan-errors")
    @fixture = ReleaseFixture.new(@dir)
    @good = @fixture.repository("good", [%w[bionic amd64], %w[buster amd64]], { "base/cmake" => {} })
    @server = HttpServer.new(@good)
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  # An ancestor named +name+ whose repository is a copy of the good one,
  # broken by the block (local), or the good one served with HTTP faults.
  def plan_child_of(name, repository)
    @fixture.spec(name, "targets: { bionic: [amd64], buster: [amd64] }\nrepository: { #{repository}, trusted: true }\n")
    child = "child-of-#{name}"
    @fixture.spec(child, "parent: #{name}\n")
    run = relspec("plan", "specs/#{child}.yml", "--write", "--timeout", "0.5", chdir: @dir)
    expect(run.exit_code).to eq(1)
    expect(run.stdout).to eq("")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(File.exist?(File.join(@dir, "releases", child, "lock.yml"))).to be(false)
    run.stderr
  end

  def broken_copy(name)
    path = File.join(@dir, "repos", name)
    FileUtils.cp_r(@good, path)
    yield path
    "path: ../repos/#{name}"
  end

  it "names the ancestor and the file whose SHA256 does not match" do
    repository = broken_copy("tampered") do |path|
      File.binwrite(File.join(path, "dists/buster/main/binary-amd64/Packages.gz"), Zlib.gzip("Package: x\nVersion: 1\n"))
    end
    expect(plan_child_of("tampered", repository)).to start_with(
      "specs/tampered.yml:4:1: error[ancestor-repository]: ancestor tampered: #{@dir}/repos/tampered/dists/buster/main/" \
      "binary-amd64/Packages.gz does not match the SHA256 of the Release file"
    )
  end

  it "names a truncated index" do
    repository = broken_copy("truncated") do |path|
      gz = File.binread(File.join(path, "dists/bionic/main/binary-amd64/Packages.gz"))
      ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages.gz", gz[0, 20])
    end
    expect(plan_child_of("truncated", repository)).to include("ancestor truncated: #{@dir}/repos/truncated/dists/bionic/" \
                                                              "main/binary-amd64/Packages.gz: corrupt gzip data")
  end

  it "names a missing codename" do
    repository = broken_copy("nobuster") { |path| FileUtils.rm_rf(File.join(path, "dists", "buster")) }
    expect(plan_child_of("nobuster", repository))
      .to include("ancestor nobuster: #{@dir}/repos/nobuster has no distribution buster")
  end

  it "names a malformed stanza with its line" do
    repository = broken_copy("malformed") do |path|
      ReleaseFileEditor.keep_only(path, "bionic", "main/binary-amd64", "main/binary-amd64/Packages")
      ReleaseFileEditor.replace_index(path, "bionic", "main/binary-amd64/Packages", "Package: a\nVersion: 1\n\nbroken\n")
    end
    expect(plan_child_of("malformed", repository)).to include("main/binary-amd64/Packages: malformed index: line 4:")
  end

  it "names the URL that answers 404" do
    @server.fail(%r{^/notfound/}, 404)
    expect(plan_child_of("notfound", %(url: "#{@server.url}/notfound")))
      .to include("ancestor notfound: #{@server.url}/notfound has no distribution bionic")
  end

  it "names the URL that answers 500, after bounded retries" do
    @server.fail(%r{^/failing/}, 500)
    expect(plan_child_of("failing", %(url: "#{@server.url}/failing")))
      .to include("ancestor failing: #{@server.url}/failing/dists/bionic/InRelease: HTTP 500 Internal Server Error " \
                  "(after 3 attempts, ")
  end

  it "names the URL of a server that stalls" do
    @server.fail(%r{^/stalling/}, :stall, seconds: 2)
    expect(plan_child_of("stalling", %(url: "#{@server.url}/stalling")))
      .to include("ancestor stalling: #{@server.url}/stalling/dists/bionic/InRelease: no answer within 0.5 s")
  end
end
