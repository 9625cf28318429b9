# frozen_string_literal: true

require "spec_helper"
require "webrick"

# Hostile servers and repository files (issue 12, cases 3, 8 and 9), through
# the real CLI: a server dripping bytes or sending an endless body meets the
# overall deadline or the size cap; a Release that is a FIFO or a link to
# /dev/zero, and an empty Release.gpg, are refused with one true message.
RSpec.describe "relspec plan against hostile repositories" do
  # A real WEBrick server on 127.0.0.1 serving +root+, except for paths
  # that drip one byte every 50 ms or stream without end.
  class HostileServer
    def initialize(root)
      @root = root
      @behaviours = {}
      @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: 0, Logger: WEBrick::Log.new(File::NULL),
                                        AccessLog: [])
      @server.mount_proc("/") { |request, response| serve(request, response) }
      @thread = Thread.new { @server.start }
    end

    def url
      "http://127.0.0.1:#{@server.config[:Port]}"
    end

    def behave(pattern, behaviour)
      @behaviours[pattern] = behaviour
    end

    def stop
      @server.shutdown
      @thread.join(5)
    end

    private

    def serve(request, response)
      path = request.path.sub(%r{\A/[^/]+}, "")
      behaviour = @behaviours.find { |pattern, _| pattern.match?(request.path) }&.last
      return stream(response, "x", 0.05) if behaviour == :drip
      return stream(response, "A" * 65_536, 0) if behaviour == :endless

      file = File.join(@root, path)
      File.file?(file) ? response.body = File.binread(file) : response.status = 404
    end

    def stream(response, piece, pause)
      StreamedBody.attach(response, piece, pause)
    end
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-hostile-network")
    @fixture = ReleaseFixture.new(@dir)
    @good = @fixture.repository("good", [%w[bionic amd64]], { "base/cmake" => {} })
    @server = HostileServer.new(@good)
  end

  after(:all) do
    @server&.stop
    FileUtils.rm_rf(@dir)
  end

  def plan_child_of(name, repository, timeout: "0.2")
    @fixture.spec(name, "targets: { bionic: [amd64] }\nrepository: { #{repository}, trusted: true }\n")
    child = "child-of-#{name}"
    @fixture.spec(child, "parent: #{name}\n")
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    run = relspec("plan", "specs/#{child}.yml", "--write", "--timeout", timeout, chdir: @dir)
    @elapsed = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
    expect(run.exit_code).to eq(1), run.stderr
    expect(run.stdout).to eq("")
    expect(run.stderr).not_to match(/\.rb:\d+:in /)
    expect(File.exist?(File.join(@dir, "releases", child, "lock.yml"))).to be(false)
    run.stderr
  end

  it "gives a download dripping one byte at a time an overall deadline, and says how long it took" do
    @server.behave(%r{\A/drip/dists/bionic/InRelease}, :drip)
    message = plan_child_of("drip", %(url: "#{@server.url}/drip"))
    # --timeout 0.2: each read is answered in time, the whole is cut at 12 × 0.2 s
    expect(message).to match(%r{#{@server.url}/drip/dists/bionic/InRelease: not complete after 2\.\d s, the deadline of a download \(12 × --timeout 0\.2; after 1 attempt\)})
    expect(@elapsed).to be < 20
  end

  it "stops an endless Release at its cap" do
    @server.behave(%r{\A/endless/dists/bionic/InRelease}, :endless)
    expect(plan_child_of("endless", %(url: "#{@server.url}/endless"), timeout: "5"))
      .to include("#{@server.url}/endless/dists/bionic/InRelease: the server sends more than 16777216 bytes, " \
                  "the most this file can hold; stopped")
  end

  it "never reads an index past the size its Release file gives" do
    @server.behave(%r{\A/endless-index/dists/bionic/main/binary-amd64/}, :endless)
    expect(plan_child_of("endless-index", %(url: "#{@server.url}/endless-index"), timeout: "5"))
      .to match(%r{/endless-index/dists/bionic/main/binary-amd64/Packages\.\w+: the server sends more than \d+ bytes, the most this file can hold; stopped})
  end

  def local_copy(name)
    path = File.join(@dir, "repos", name)
    FileUtils.cp_r(@good, path)
    FileUtils.rm_f(File.join(path, "dists", "bionic", "InRelease"))
    yield File.join(path, "dists", "bionic")
    "path: ../repos/#{name}"
  end

  it "refuses a Release that is a FIFO instead of waiting for it forever" do
    repository = local_copy("fifo") do |dists|
      FileUtils.rm_f(File.join(dists, "Release"))
      File.mkfifo(File.join(dists, "Release"))
    end
    expect(plan_child_of("fifo", repository)).to include("repos/fifo/dists/bionic/Release: not a regular file (fifo)")
  end

  it "refuses a Release linked to /dev/zero instead of reading it without end" do
    repository = local_copy("zero") do |dists|
      FileUtils.rm_f(File.join(dists, "Release"))
      File.symlink("/dev/zero", File.join(dists, "Release"))
    end
    expect(plan_child_of("zero", repository)).to include("repos/zero/dists/bionic/Release: not a regular file (characterSpecial)")
  end
end
