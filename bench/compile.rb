# frozen_string_literal: true

# bench/compile: `relspec compile` of a generated 400-package release (one
# target, every package built: its parent has none), then the same compile
# again with nothing changed — which must take < 1 s and rewrite nothing.
# The peer is the first, full compile in the same run.
#
#   bundle exec ruby bench/compile.rb [PACKAGES] [RUNS]
require "digest"
require "fileutils"
require "open3"
require "rbconfig"
require "tmpdir"
require_relative "../spec/support/workspace_builder"

ROOT = File.expand_path("..", __dir__)
COUNT = Integer(ARGV.fetch(0, "400"))
RUNS = Integer(ARGV.fetch(1, "3"))

def relspec(*args, chdir:)
  started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
  output, status = Open3.capture2e(RbConfig.ruby, File.join(ROOT, "exe", "relspec"), *args, chdir: chdir)
  raise "relspec #{args.join(' ')} failed:\n#{output}" unless status.success?

  [Process.clock_gettime(Process::CLOCK_MONOTONIC) - started, output]
end

def snapshot(dir)
  Dir.glob("**/*", File::FNM_DOTMATCH, base: dir).sort.to_h do |path|
    full = File.join(dir, path)
    [path, File.file?(full) ? [File.mtime(full), Digest::SHA256.file(full).hexdigest] : :dir]
  end
end

KEEP = ENV.fetch("RELSPEC_BENCH_KEEP", nil)
run_in = lambda { |&block|
  if KEEP
    (FileUtils.mkdir_p(KEEP)
     block.call(KEEP))
  else
    Dir.mktmpdir("relspec-bench-compile", &block)
  end
}
run_in.call do |dir|
  builder = WorkspaceBuilder.new(File.join(dir, "ws"), package_set: "bench.pkgs")
  COUNT.times do |i|
    dependencies = [i / 2, i / 3].uniq.select { |d| d.positive? && d < i }.map { |d| "pkg/p#{d}" }
    builder.package("pkg/p#{i}", type: :cmake, date: "2020-06-01T00:00:00Z", dependencies: dependencies,
                                 files: { "CMakeLists.txt" => "cmake_minimum_required(VERSION 3.10)\nproject(p#{i} NONE)\n" })
  end
  builder.layout("bench.pkgs")
  builder.create
  FileUtils.mkdir_p(File.join(dir, "specs"))
  File.write(File.join(dir, "specs", "bench.yml"), "release: bench\nworkspace: ../ws/workspace\ntargets: { bionic: [amd64] }\n" \
                                                   "maintainer: Bench <bench@example.org>\n")
  full, = relspec("compile", "specs/bench.yml", chdir: dir)
  before = snapshot(File.join(dir, "build"))
  noop = Array.new(RUNS) { relspec("compile", "specs/bench.yml", chdir: dir) }
  times = noop.map(&:first).sort
  unchanged = snapshot(File.join(dir, "build")) == before
  puts "#{COUNT} packages, one target"
  puts format("%-40s %8.2f s", "first compile (everything emitted)", full)
  puts format("%-40s %8.2f s  (median of #{RUNS}; target < 1 s)", "compile with nothing changed", times[RUNS / 2])
  puts "files rewritten by the no-op compiles: #{unchanged ? 'none' : 'SOME'}; it said: #{noop.last.last.lines.last.strip}"
end
