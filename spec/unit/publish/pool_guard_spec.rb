# frozen_string_literal: true

require_relative "../unit_helper"
require "relspec/publish/pool_guard"
require "relspec/publish/upload"

# One name, one set of bytes in a repository's pool; but a file the
# database does not hold was never published (a reprepro killed while
# copying leaves it, often empty: the hostile publish-kill test met one under
# load) and must not stop the next publish.
RSpec.describe Relspec::Publish::PoolGuard, :tmpdir do
  let(:pool) { "pool/main/r/rock-r-a/rock-r-a_1.0-1~bookworm.dsc" }
  let(:local) { File.join(@dir, "out", "rock-r-a_1.0-1~bookworm.dsc").tap { |path| write(path, "the dsc\n") } }
  let(:held) { File.join(@dir, "repo", pool) }
  let(:items) { [Relspec::Publish::Upload::Item.new(local: local, pool: pool)] }

  def write(path, text)
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, text)
  end

  it "refuses other bytes under a published name, naming both files" do
    write(held, "other bytes\n")
    expect { described_class.check(File.join(@dir, "repo"), items, published: [pool]) }
      .to raise_error(Relspec::PublishError, /#{Regexp.escape(local)} .* differs from #{Regexp.escape(held)} .*already published/)
    expect(File.read(held)).to eq("other bytes\n")
  end

  it "accepts the same bytes, and removes what an interrupted reprepro left under a name the database lacks" do
    write(held, "the dsc\n")
    expect { described_class.check(File.join(@dir, "repo"), items, published: [pool]) }.not_to raise_error
    write(held, "")
    expect { described_class.check(File.join(@dir, "repo"), items, published: []) }.not_to raise_error
    expect(File.exist?(held)).to be(false)
  end

  it "refuses two different files for one name in one batch" do
    other = File.join(@dir, "elsewhere", "rock-r-a_1.0-1~bookworm.dsc").tap { |path| write(path, "else\n") }
    both = items + [Relspec::Publish::Upload::Item.new(local: other, pool: pool)]
    expect { described_class.check(File.join(@dir, "repo"), both, published: []) }
      .to raise_error(Relspec::PublishError, /both to be published as #{Regexp.escape(pool)}/)
  end
end
