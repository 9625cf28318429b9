# frozen_string_literal: true

require "spec_helper"
require "relspec/apt/cache"
require "relspec/apt/host_lists"
require "relspec/plan/archive_versions"
require "relspec/plan/target"

# On this machine's own apt lists (bin/setup runs apt-get update): Debian's
# main index is parsed once, then read from the cache under its SHA256.
RSpec.describe Relspec::Plan::ArchiveVersions, :tmpdir do
  let(:arch) { `dpkg --print-architecture`.strip }
  let(:target) { Relspec::Plan::Target.new("bookworm", arch) }
  let(:lists) { Relspec::Apt::HostLists.new }
  let(:cache) { Relspec::Apt::Cache.new(@dir) }

  it "parses the index once, then reads the same versions from the cache" do
    allow(lists).to receive(:packages).and_call_original
    parsed = described_class.of(lists, target, "main", cache)
    index = Relspec::Apt::PackageIndex.parse(lists.packages_text("bookworm", arch))
    expect(parsed.version("dpkg")).to eq(index["dpkg"].version)
    expect(parsed.names.size).to eq(index.size)
    # Ruby's default gems, provided by libruby3.1
    expect(parsed.enum_for(:each_provided, /\Aruby-json\z/).to_a).not_to be_empty

    cached = described_class.of(lists, target, "main", cache)
    expect(lists).to have_received(:packages).once
    expect(cached.dump).to eq(parsed.dump)

    entry = Dir.glob(File.join(@dir, "*", described_class::CACHE_ENTRY)).first
    File.write(entry, File.read(entry).sub(/^dpkg .*$/, "dpkg 99.0"))
    expect(described_class.of(lists, target, "main", cache).version("dpkg")).to eq(index["dpkg"].version)
    expect(lists).to have_received(:packages).twice
  end
end
