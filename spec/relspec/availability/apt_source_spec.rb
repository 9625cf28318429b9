# frozen_string_literal: true

require "spec_helper"
require "relspec/availability/apt_source"
require "relspec/apt/host_lists"
require "relspec/plan/target"

RSpec.describe Relspec::Availability::AptSource do
  def target(text)
    Relspec::Plan::Target.parse(text)
  end

  def names_cache
    Relspec::Apt::Cache.new(@cache_dir)
  end

  def local(repository)
    Relspec::Apt::Repository.new(Relspec::Apt::Fetcher.new(repository), trusted: true)
  end

  before(:all) do
    @dir = Dir.mktmpdir("relspec-apt-source")
    @repo = File.join(@dir, "archive")
    builder = AptRepositoryBuilder.new(@repo, codenames: %w[jammy jammy-updates], architectures: %w[amd64 arm64])
    builder.add_many([{ name: "libfoo1.2-dev", version: "1.2-1", arch: "amd64" },
                      { name: "data-common", version: "1", arch: "all" },
                      { name: "libbar-dev", version: "2-1", arch: "amd64", provides: "libbar-virtual-dev (= 2)" }],
                     codename: "jammy")
    builder.add("libnew-dev", "1-1", codename: "jammy-updates", arch: "amd64")
  end

  after(:all) { FileUtils.rm_rf(@dir) }

  around do |example|
    Dir.mktmpdir("relspec-names") do |cache|
      @cache_dir = cache
      example.run
    end
  end

  it "finds names directly, through Provides, as Architecture: all and in -updates; not on another architecture" do
    source = described_class.new(local(@repo), ["main"], names_cache: names_cache)
    wanted = %w[libfoo1.2-dev data-common libbar-virtual-dev libnew-dev libfoo1.3-dev]
    answers = source.lookup_many({ target("jammy/amd64") => wanted, target("jammy/arm64") => wanted })
    expect(answers[target("jammy/amd64")]).to eq([{ "libfoo1.2-dev" => true, "data-common" => true,
                                                    "libbar-virtual-dev" => true, "libnew-dev" => true,
                                                    "libfoo1.3-dev" => false }, nil])
    expect(answers[target("jammy/arm64")][0]).to eq("libfoo1.2-dev" => false, "data-common" => true,
                                                    "libbar-virtual-dev" => false, "libnew-dev" => false,
                                                    "libfoo1.3-dev" => false)
    expect(source.hint(target("jammy/amd64"), "libfoo1.3-dev")).to eq("libfoo1.2-dev")
  end

  it "says why a target cannot be answered (architecture or codename the archive lacks)" do
    source = described_class.new(local(@repo), ["main"], names_cache: names_cache)
    answers = source.lookup_many({ target("jammy/riscv64") => ["x"], target("noble/amd64") => ["x"] })
    expect(answers[target("jammy/riscv64")][0]).to eq("x" => nil)
    expect(answers[target("jammy/riscv64")][1]).to include("lists no main/binary-riscv64")
    expect(answers[target("noble/amd64")][1]).to include("has no distribution noble")
  end

  it "reads over HTTP, and parses an unchanged index only once (names cached by its Release checksum)" do
    server = HttpServer.new(@repo)
    reader = -> { Relspec::Apt::Repository.new(Relspec::Apt::Fetcher.new(server.url), trusted: true) }
    described_class.new(reader.call, ["main"], names_cache: names_cache).lookup_many({ target("jammy/amd64") => ["data-common"] })
    expect(server.requests.grep(/Packages/)).not_to be_empty
    server.requests.clear
    again = described_class.new(reader.call, ["main"], names_cache: names_cache)
    expect(again.lookup_many({ target("jammy/amd64") => ["libnew-dev"] })[target("jammy/amd64")][0]).to eq("libnew-dev" => true)
    expect(server.requests.grep(/Packages/)).to be_empty
    expect(server.requests).to include("/dists/jammy/InRelease").or include("/dists/jammy/Release")
  ensure
    server&.stop
  end

  it "reads this machine's own bookworm lists (apt-get indextargets, verified against the stored InRelease)" do
    source = described_class.new(Relspec::Apt::HostLists.new, ["main"], names_cache: names_cache)
    bookworm = target("bookworm/#{`dpkg --print-architecture`.strip}")
    found, problem = source.lookup_many({ bookworm => %w[cmake debhelper-compat libboost-system1.67-dev] })[bookworm]
    expect(problem).to be_nil
    expect(found).to eq("cmake" => true, "debhelper-compat" => true, "libboost-system1.67-dev" => false)
    # another soname of the same library (bookworm has 1.74 and 1.81; the newest is offered)
    hint = source.hint(bookworm, "libboost-system1.67-dev")
    expect(hint).to match(/\Alibboost-system1\.(7[4-9]|8\d)-dev\z/)
    expect(source.lookup(bookworm, [hint])).to eq(hint => true)
  end
end
