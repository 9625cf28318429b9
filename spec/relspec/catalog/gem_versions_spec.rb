# frozen_string_literal: true

require "spec_helper"
require "webrick"
require "relspec/catalog/gem_versions"

# Listing a gem's versions from gem_source: a folder of .gem files, or a
# real WEBrick server answering the compact index (/info/<name>) as
# rubygems.org does, including servers that never stop sending.
RSpec.describe Relspec::Catalog::GemVersions do
  before(:all) do
    @server = WEBrick::HTTPServer.new(BindAddress: "127.0.0.1", Port: 0, Logger: WEBrick::Log.new(File::NULL), AccessLog: [])
    @server.mount_proc("/info/foo") do |_, response|
      # as rubygems.org writes it: platform gems and prereleases among the releases
      response.body = "---\n1.0.0 bar:>= 1.0|checksum:aa\n1.10.0 |checksum:bb\n1.10.0-java |checksum:cc\n" \
                      "2.0.0.rc1 |checksum:dd\n1.9.1 |checksum:ee,ruby:>= 2.5\n"
    end
    @server.mount_proc("/info/rubies") do |_, response|
      response.body = "---\n1.0.0 |checksum:aa,ruby:>= 2.7&< 4,created_at:2020-01-01T00:00:00Z\n2.0.0 |checksum:bb,ruby:>= banana\n" \
                      "3.0.0 a:>= 1,b:< 2|checksum:cc\n"
    end
    @server.mount_proc("/info/endless") { |_, response| StreamedBody.attach(response, "9.9.9 |checksum:ff\n" * 4096, 0) }
    @server.mount_proc("/info/html") { |_, response| response.body = "<html><body>Proxy login</body></html>\n" }
    @server.mount_proc("/info/cut") { |_, response| response.body = "---\n1.0.0 |checksum:aa\n1.1.0 |chec" }
    @server.mount_proc("/info/binary") { |_, response| response.body = "\x1F\x8B\x08\x00\xFF".b }
    @server.mount_proc("/info/drip") { |_, response| StreamedBody.attach(response, "1", 0.05) }
    @thread = Thread.new { @server.start }
    @url = "http://127.0.0.1:#{@server.config[:Port]}"
  end

  after(:all) do
    @server.shutdown
    @thread.join(5)
  end

  it "reads the compact index: releases only, highest first" do
    expect(described_class.new(@url, base_dir: "/").of("foo").map(&:to_s)).to eq(%w[1.10.0 1.9.1 1.0.0])
  end

  # dry-core 1.2.0's line says "ruby:>= 3.2": a hint that spares its download on a Ruby 3.1 target
  it "gives the Ruby the compact index says a version needs, none where it says none or what it says is no requirement" do
    versions = described_class.new(@url, base_dir: "/")
    expect(versions.required_ruby("foo", "1.9.1")).to eq(Gem::Requirement.new(">= 2.5"))
    expect(versions.required_ruby("foo", "1.10.0")).to be_nil
    expect(versions.required_ruby("rubies", "1.0.0")).to eq(Gem::Requirement.new(">= 2.7", "< 4"))
    expect(versions.required_ruby("rubies", "2.0.0")).to be_nil
    expect(versions.required_ruby("rubies", "3.0.0")).to be_nil
    expect(versions.required_ruby("nothing", "1.0.0")).to be_nil
  end

  it "has no versions of a gem the server does not know" do
    expect(described_class.new(@url, base_dir: "/").of("nothing")).to eq([])
  end

  {
    "an HTML page" => ["html", ':1: not a compact index line ("VERSION DEPENDENCIES|checksum:SHA256"): "<html><body>Proxy login</body></html>"'],
    "a truncated index" => ["cut", ':3: not a compact index line ("VERSION DEPENDENCIES|checksum:SHA256"): "1.1.0 |chec"'],
    "a binary answer" => ["binary", ": not a compact index (not UTF-8 text)"]
  }.each do |what, (name, message)|
    it "refuses #{what} as the compact index, naming the URL and line (never 'no versions')" do
      expect { described_class.new(@url, base_dir: "/").of(name) }
        .to raise_error(described_class::Problem, "#{@url}/info/#{name}#{message}")
    end
  end

  it "stops an endless index at its size cap" do
    stub_const("#{described_class}::MAX_BYTES", 1024 * 1024)
    expect { described_class.new(@url, base_dir: "/").of("endless") }
      .to raise_error(described_class::Problem, /cannot list the versions of gem endless: .*more than 1048576 bytes/)
  end

  it "stops a dripping index at the download deadline" do
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    expect { described_class.new(@url, base_dir: "/", timeout: 0.2).of("drip") }
      .to raise_error(described_class::Problem, /cannot list the versions of gem drip: /)
    expect(Process.clock_gettime(Process::CLOCK_MONOTONIC) - started).to be < 10
  end

  it "lists a folder's .gem files of that name, not of a longer one" do
    Dir.mktmpdir("relspec-gem-folder") do |dir|
      %w[foo-1.0.0.gem foo-2.0.0.gem foo-bar-3.0.0.gem foo-2.1.0-x86_64-linux.gem foo-3.0.0.pre.gem notes.txt]
        .each { |file| File.write(File.join(dir, file), "") }
      expect(described_class.new(File.basename(dir), base_dir: File.dirname(dir)).of("foo").map(&:to_s))
        .to eq(%w[2.0.0 1.0.0])
      expect { described_class.new("absent", base_dir: dir).of("foo") }
        .to raise_error(described_class::Problem, "gem_source absent is not a folder")
    end
  end
end
