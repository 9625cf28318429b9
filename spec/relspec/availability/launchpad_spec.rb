# frozen_string_literal: true

require "spec_helper"
require "relspec/availability/launchpad_client"
require "relspec/availability/launchpad_source"
require "relspec/availability/answer_cache"
require "relspec/plan/target"

# The Launchpad client and source against a local server that answers in
# Launchpad's documented JSON shapes (see spec/support/launchpad_server.rb
# for which responses are modelled on what).
RSpec.describe Relspec::Availability::LaunchpadClient do
  let(:pauses) { [] }

  def client(server, **options)
    described_class.new(base: server.base, timeout: 2, backoff: 0.01, sleeper: ->(seconds) { pauses << seconds },
                        **options)
  end

  around do |example|
    @server = LaunchpadServer.new({ "jammy/amd64" => %w[cmake libboost-system1.74-dev libboost-system1.74.0 debhelper],
                                    "jammy/arm64" => %w[cmake] }, page_size: 2)
    example.run
  ensure
    @server.stop
  end

  it "asks getPublishedBinaries with the documented parameters" do
    entries = client(@server).published_binaries("cmake", "jammy", "amd64")
    expect(entries.map { |entry| entry["binary_package_name"] }).to eq(["cmake"])
    query = @server.requests.first
    expect(query).to include("ws.op" => "getPublishedBinaries", "binary_name" => "cmake", "exact_match" => "true",
                             "status" => "Published", "distro_arch_series" => "#{@server.base}/ubuntu/jammy/amd64")
  end

  it "follows next_collection_link until the last page" do
    entries = client(@server).published_binaries("libboost", "jammy", "amd64", exact: false)
    expect(entries.map { |entry| entry["binary_package_name"] }).to eq(%w[libboost-system1.74-dev libboost-system1.74.0])
    @server.stop
    paged = LaunchpadServer.new({ "jammy/amd64" => %w[a-lib1 a-lib2 a-lib3 a-lib4 a-lib5] }, page_size: 2)
    lp = client(paged)
    names = lp.published_binaries("a-lib", "jammy", "amd64", exact: false).map { |entry| entry["binary_package_name"] }
    expect(names).to eq(%w[a-lib1 a-lib2 a-lib3 a-lib4 a-lib5])
    expect(paged.requests.map { |query| query["ws.start"] }).to eq([nil, "2", "4"])
    expect(lp.requests).to eq(3)
  ensure
    paged&.stop
  end

  it "says which series Launchpad does not know (404), without retrying" do
    lp = client(@server)
    expect { lp.published_binaries("cmake", "hirsute", "amd64") }
      .to raise_error(described_class::UnknownSeries, %r{no Ubuntu series/architecture hirsute/amd64 .*HTTP 404})
    expect(lp.requests).to eq(1)
  end

  it "retries a 503 with growing pauses and then succeeds" do
    @server.fail("cmake", 503, 503)
    lp = client(@server)
    expect(lp.published_binaries("cmake", "jammy", "amd64").size).to eq(1)
    expect(lp.requests).to eq(3)
    expect(pauses).to eq([0.01, 0.02])
  end

  it "honours Retry-After on a 429" do
    @server.fail("cmake", [429, 3])
    lp = client(@server)
    expect(lp.published_binaries("cmake", "jammy", "amd64").size).to eq(1)
    expect(pauses).to eq([3])
  end

  it "gives up after the bounded number of attempts, naming the URL" do
    @server.fail("cmake", 503, 503, 503, 503)
    expect { client(@server, retries: 3).published_binaries("cmake", "jammy", "amd64") }
      .to raise_error(described_class::Failure, /HTTP 503 .*after 3 attempts/)
    expect(@server.requests.size).to eq(3)
  end

  it "refuses a Retry-After longer than it is willing to wait" do
    @server.fail("cmake", [429, 3600])
    expect { client(@server).published_binaries("cmake", "jammy", "amd64") }
      .to raise_error(described_class::Failure, /asked to wait 3600 s/)
  end

  it "gives a page dripping one byte at a time an overall deadline" do
    @server.fail("cmake", :drip)
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    expect { client(@server, timeout: 0.2, retries: 1).published_binaries("cmake", "jammy", "amd64") }
      .to raise_error(described_class::Failure, /not complete after 2\.\d s, the deadline of a page \(12 × the timeout 0\.2 s; after 1 attempts\)/)
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 5
  end

  it "stops reading an endless answer at its cap" do
    @server.fail("cmake", :endless)
    expect { client(@server, timeout: 5, retries: 1).published_binaries("cmake", "jammy", "amd64") }
      .to raise_error(described_class::Failure, /the answer is larger than 8388608 bytes \(MAX_ANSWER_BYTES\); stopped/)
  end

  it "times out an answer slower than the timeout, retries, and reports when it never comes" do
    @server.fail("cmake", [:slow, 1.5])
    lp = client(@server, timeout: 0.5)
    expect(lp.published_binaries("cmake", "jammy", "amd64").size).to eq(1)
    expect(lp.requests).to eq(2)
    @server.fail("debhelper", [:slow, 1.5], [:slow, 1.5])
    expect { client(@server, timeout: 0.5, retries: 2).published_binaries("debhelper", "jammy", "amd64") }
      .to raise_error(described_class::Failure, /no answer within 0.5 s \(after 2 attempts\)/)
  end
end

RSpec.describe Relspec::Availability::LaunchpadSource do
  let(:jammy) { Relspec::Plan::Target.new("jammy", "amd64") }
  let(:jammy_arm) { Relspec::Plan::Target.new("jammy", "arm64") }
  let(:noble) { Relspec::Plan::Target.new("noble", "amd64") }

  around do |example|
    Dir.mktmpdir("relspec-lp-cache") do |dir|
      @cache_dir = dir
      @now = 1_000_000
      example.run
    end
  end

  def cache
    Relspec::Availability::AnswerCache.new(@cache_dir, clock: -> { @now })
  end

  def source(server, concurrency: 4)
    client = Relspec::Availability::LaunchpadClient.new(base: server.base, timeout: 2, backoff: 0.01, sleeper: ->(_) {})
    described_class.new(client: client, cache: cache, concurrency: concurrency)
  end

  it "asks once per distinct (name, series, arch), and nothing again within the TTL" do
    server = LaunchpadServer.new({ "jammy/amd64" => %w[cmake debhelper libeigen3-dev], "jammy/arm64" => %w[cmake] })
    wanted = { jammy => %w[cmake debhelper-compat libeigen3-dev libnope-dev], jammy_arm => %w[cmake libeigen3-dev] }
    answers = source(server).lookup_many(wanted)
    expect(answers[jammy]).to eq([{ "cmake" => true, "debhelper-compat" => true, "libeigen3-dev" => true,
                                    "libnope-dev" => false }, nil])
    expect(answers[jammy_arm]).to eq([{ "cmake" => true, "libeigen3-dev" => false }, nil])
    asked = server.requests.map { |query| [query["binary_name"], query["distro_arch_series"][%r{\w+/\w+\z}]] }
    expect(asked.sort).to eq([["cmake", "jammy/amd64"], ["cmake", "jammy/arm64"], ["debhelper", "jammy/amd64"],
                              ["libeigen3-dev", "jammy/amd64"], ["libeigen3-dev", "jammy/arm64"],
                              ["libnope-dev", "jammy/amd64"]])

    @now += 600 # within both TTLs
    expect(source(server).lookup_many(wanted)).to eq(answers)
    expect(server.requests.size).to eq(6)

    @now += Relspec::Availability::AnswerCache::MISSING_TTL # missing answers expire first
    source(server).lookup_many(wanted)
    expect(server.requests.size).to eq(8)
    expect(server.names_asked.last(2).sort).to eq(%w[libeigen3-dev libnope-dev])
  ensure
    server&.stop
  end

  it "answers from the cache alone without a client, leaving the rest unknown" do
    server = LaunchpadServer.new({ "jammy/amd64" => %w[cmake] })
    source(server).lookup_many({ jammy => ["cmake"] })
    offline = described_class.new(client: nil, cache: cache, base: server.base)
    expect(offline.lookup_many({ jammy => %w[cmake git] })).to eq({ jammy => [{ "cmake" => true, "git" => nil }, nil] })
  ensure
    server&.stop
  end

  it "reports an unknown series once for the target and never caches a failure" do
    server = LaunchpadServer.new({ "jammy/amd64" => %w[cmake] })
    server.fail("git", 503, 503, 503, 503)
    answers = source(server, concurrency: 1).lookup_many({ noble => %w[cmake git ruby], jammy => %w[cmake git] })
    found, problem = answers[noble]
    expect(problem).to match(%r{no Ubuntu series/architecture noble/amd64})
    expect(found.values).to all(be_nil)
    expect(server.requests.count { |query| query["distro_arch_series"].end_with?("noble/amd64") }).to eq(1)
    expect(answers[jammy][1]).to match(/HTTP 503/)
    expect(cache.read([server.base, "git", "jammy", "amd64"].join("\n"))).to be_nil
    expect(cache.read([server.base, "cmake", "jammy", "amd64"].join("\n"))).to be(true)
  ensure
    server&.stop
  end

  it "keeps at most the concurrency limit of requests in flight, and uses it" do
    names = Array.new(12) { |i| "lib#{i}-dev" }
    server = LaunchpadServer.new({ "jammy/amd64" => names }, delay: 0.2)
    source(server, concurrency: 3).lookup_many({ jammy => names })
    expect(server.requests.size).to eq(12)
    expect(server.max_in_flight).to eq(3)
  ensure
    server&.stop
  end

  it "suggests a published name that differs only in its numbers" do
    server = LaunchpadServer.new({ "jammy/amd64" => %w[libboost-system1.74-dev libboost-system1.74.0 libboost-dev] })
    expect(source(server).hint(jammy, "libboost-system1.83-dev")).to eq("libboost-system1.74-dev")
  ensure
    server&.stop
  end
end
