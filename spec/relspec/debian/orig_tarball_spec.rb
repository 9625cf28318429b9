# frozen_string_literal: true

require "spec_helper"
require "relspec/debian/orig_tarball"

RSpec.describe Relspec::Debian::OrigTarball, :tmpdir do
  def listing(path)
    output, status = Open3.capture2("tar", "-tzvf", path)
    expect(status).to be_success
    output.lines
  end

  it "makes the same bytes from a git commit, whatever the checkout's state, with the commit's time" do
    builder = WorkspaceBuilder.new(@dir)
    repo = File.join(@dir, "repo")
    FileUtils.mkdir_p(repo)
    builder.git(repo, "init", "-q")
    File.write(File.join(repo, "a.txt"), "a\n")
    builder.git(repo, "add", "-A")
    builder.git(repo, "commit", "-q", "-m", "a", date: "2020-06-01T10:30:00Z")
    commit = builder.git(repo, "rev-parse", "HEAD")
    File.write(File.join(repo, "untracked.o"), "build product\n")
    FileUtils.mkdir_p(File.join(repo, "build"))
    files = Array.new(2) do |i|
      path = File.join(@dir, "#{i}.orig.tar.gz")
      described_class.write(path, checkout: repo, commit: commit, prefix: "pkg-1.0", mtime: nil)
      path
    end
    expect(File.binread(files[0])).to eq(File.binread(files[1]))
    entries = listing(files[0])
    expect(entries.map { |line| line.split.last }).to eq(["pkg-1.0/", "pkg-1.0/a.txt"])
    expect(entries.last).to include("root/root", "2020-06-01 10:30")
    expect(File.binread(files[0], 4, 4).unpack1("V")).to eq(0) # gzip -n: no time stamp
  end

  it "makes the same bytes from a plain tree, sorted, normalised, with paths over 256 bytes" do
    tree = File.join(@dir, "tree")
    long = File.join(tree, *Array.new(6) { |i| "directory-with-a-long-name-#{i}-#{'x' * 30}" }, "file.txt")
    FileUtils.mkdir_p(File.dirname(long))
    File.write(long, "deep\n")
    File.write(File.join(tree, "b.txt"), "b\n")
    File.write(File.join(tree, "a.txt"), "a\n")
    File.chmod(0o600, File.join(tree, "a.txt"))
    FileUtils.mkdir_p(File.join(tree, ".git"))
    File.write(File.join(tree, ".git", "HEAD"), "x")
    mtime = Time.utc(2019, 11, 11, 11, 11, 11)
    first = File.join(@dir, "first.tar.gz")
    second = File.join(@dir, "second.tar.gz")
    described_class.write(first, checkout: tree, commit: nil, prefix: "pkg-0.1", mtime: mtime)
    FileUtils.touch(File.join(tree, "b.txt")) # mtimes on disk do not matter
    described_class.write(second, checkout: tree, commit: nil, prefix: "pkg-0.1", mtime: mtime)
    expect(File.binread(first)).to eq(File.binread(second))
    names = listing(first).map { |line| line.split.last }
    expect(names.first(3)).to eq(["pkg-0.1/", "pkg-0.1/a.txt", "pkg-0.1/b.txt"])
    expect(names).to include("pkg-0.1/#{long.delete_prefix("#{tree}/")}")
    expect(names.grep(/\.git/)).to be_empty
    expect(listing(first)[1]).to start_with("-rw-r--r-- 0/0")
  end

  it "keeps symbolic links' targets, tracked build/ folders and .gitignore of a whole tree (gems)" do
    tree = File.join(@dir, "gem")
    FileUtils.mkdir_p(File.join(tree, "src", "inc"))
    FileUtils.mkdir_p(File.join(tree, "build"))
    File.write(File.join(tree, "src", "inc", "a.h"), "int a;\n")
    File.write(File.join(tree, "build", "extconf.rb"), "# part of the gem\n")
    File.write(File.join(tree, ".gitignore"), "*.o\n")
    File.symlink("src/inc", File.join(tree, "include"))
    path = File.join(@dir, "gem.tar.gz")
    described_class.write(path, checkout: tree, commit: nil, prefix: "pkg-1.0", mtime: Time.utc(2020), everything: true)
    entries = listing(path)
    expect(entries.grep(%r{ pkg-1\.0/include -> }).first).to end_with("pkg-1.0/include -> src/inc\n")
    expect(entries.map { |line| line.split.last }).to include("pkg-1.0/build/extconf.rb", "pkg-1.0/.gitignore")
  end
end
