# frozen_string_literal: true

require "spec_helper"
require "relspec/catalog/git_state"

# The .git reader must agree with git itself for the layouts git produces:
# loose objects, packs after gc, packed refs, detached HEADs.
RSpec.describe Relspec::Catalog::GitRepository do
  around do |example|
    Dir.mktmpdir("relspec-git") do |dir|
      @dir = dir
      @builder = WorkspaceBuilder.new(dir)
      @builder.git(dir, "init", "-q")
      example.run
    end
  end

  def commit(date, content)
    File.write(File.join(@dir, "file"), content)
    @builder.git(@dir, "add", "-A")
    @builder.git(@dir, "commit", "-q", "-m", content, date: date)
  end

  def git_head
    sha, seconds = @builder.git(@dir, "log", "-1", "--format=%H %ct").split
    [sha, Integer(seconds)]
  end

  it "reads a loose commit" do
    commit("2021-02-03T04:05:06Z", "one")
    expect(described_class.new(@dir).head).to eq(git_head)
    expect(git_head[1]).to eq(Time.utc(2021, 2, 3, 4, 5, 6).to_i)
  end

  it "reads a packed commit behind packed refs" do
    30.times { |i| commit("2021-02-03T04:05:#{format('%02d', i)}Z", "content #{i}\n" * 50) }
    @builder.git(@dir, "gc", "-q", "--aggressive")
    expect(Dir.glob(File.join(@dir, ".git/objects/pack/*.pack"))).not_to be_empty
    expect(File.exist?(File.join(@dir, ".git/refs/heads/master"))).to be(false)
    expect(described_class.new(@dir).head).to eq(git_head)
  end

  it "reads a detached HEAD" do
    commit("2021-01-01T00:00:00Z", "one")
    first = git_head
    commit("2021-01-02T00:00:00Z", "two")
    @builder.git(@dir, "checkout", "-q", first[0])
    expect(described_class.new(@dir).head).to eq(first)
  end

  it "gives nil for a folder that is not a repository" do
    expect(described_class.new(File.join(@dir, "nowhere")).head).to be_nil
  end

  it "is what GitState reports, in UTC" do
    commit("2021-02-03T04:05:06+02:00", "one")
    expect(Relspec::Catalog::GitState.commit_of(@dir)).to eq([git_head[0], "2021-02-03T02:05:06Z"])
  end
end
