# frozen_string_literal: true

# bench/orig: the orig tarball of a 50 MB source tree, relspec's way (git
# archive of the commit | gzip -n) next to the reference way in the same run:
# tar --sort=name --mtime=… --owner=0 --group=0 --numeric-owner | gzip -n.
# Target: ≤ 1.2×.
#
#   bundle exec ruby bench/orig.rb [MEGABYTES] [RUNS]
require "fileutils"
require "open3"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/debian/orig_tarball"

MEGABYTES = Integer(ARGV.fetch(0, "50"))
RUNS = Integer(ARGV.fetch(1, "3"))
ENVIRONMENT = { "GIT_AUTHOR_NAME" => "b", "GIT_AUTHOR_EMAIL" => "b@example.org", "GIT_COMMITTER_NAME" => "b",
                "GIT_COMMITTER_EMAIL" => "b@example.org", "GIT_AUTHOR_DATE" => "2020-06-01T00:00:00Z",
                "GIT_COMMITTER_DATE" => "2020-06-01T00:00:00Z", "GIT_CONFIG_GLOBAL" => File::NULL }.freeze

# Source-like files: text that compresses like code, in nested folders.
def make_tree(dir)
  random = Random.new(1)
  words = %w[void int return if else for while struct class namespace template std vector size_t const auto]
  total = 0
  index = 0
  while total < MEGABYTES * 1_000_000
    text = Array.new(2000) { Array.new(8) { words.sample(random: random) }.join(" ") + ";\n" }.join
    path = File.join(dir, "src", "module#{index % 40}", "file#{index}.cpp")
    FileUtils.mkdir_p(File.dirname(path))
    File.write(path, text)
    total += text.bytesize
    index += 1
  end
  system(ENVIRONMENT, "git", "-C", dir, "init", "-q", exception: true)
  system(ENVIRONMENT, "git", "-C", dir, "add", "-A", exception: true)
  system(ENVIRONMENT, "git", "-C", dir, "commit", "-q", "-m", "tree", exception: true)
  [index, total]
end

Dir.mktmpdir("relspec-bench-orig") do |dir|
  tree = File.join(dir, "tree")
  FileUtils.mkdir_p(tree)
  files, bytes = make_tree(tree)
  commit = Open3.capture2("git", "-C", tree, "rev-parse", "HEAD").first.strip
  mtime = Time.utc(2020, 6, 1)
  ours = Timing.median(RUNS) do
    Relspec::Debian::OrigTarball.write(File.join(dir, "ours.tar.gz"), checkout: tree, commit: commit, prefix: "pkg-1.0",
                                                                      mtime: mtime)
  end
  reference = Timing.median(RUNS) do
    system("tar --sort=name --mtime=@#{mtime.to_i} --owner=0 --group=0 --numeric-owner --exclude-vcs -C #{tree} " \
           "-cf - . | gzip -n > #{dir}/reference.tar.gz", exception: true)
  end
  # The same call twice gives the same bytes (the property the tests check).
  Relspec::Debian::OrigTarball.write(File.join(dir, "again.tar.gz"), checkout: tree, commit: commit, prefix: "pkg-1.0",
                                                                     mtime: mtime)
  same = File.binread(File.join(dir, "ours.tar.gz")) == File.binread(File.join(dir, "again.tar.gz"))
  puts "#{files} files, #{(bytes / 1e6).round(1)} MB"
  puts format("%-48s %8.2f s", "relspec (git archive | gzip -n)", ours)
  puts format("%-48s %8.2f s", "tar --sort=name … | gzip -n", reference)
  puts format("ratio %.2fx (target ≤ 1.2x); identical on a second run: %s", ours / reference, same)
end
