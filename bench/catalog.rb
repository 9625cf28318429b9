# frozen_string_literal: true

# bench/catalog: reading a generated workspace of 400 and 1500 packages.
#
# relspec: `relspec catalog export WORKSPACE --targets bionic` (autoproj load in
# a child process + extraction + one git call per checkout + YAML).
# Peer: autoproj's own load of the same workspace (bench/autoproj_peer_load.rb).
# Printed: median wall time, peak RSS (GNU time), and relspec's overhead on top
# of autoproj. Target: overhead < 20 %.
#
#   bundle exec ruby bench/catalog.rb [SIZES] [RUNS]      e.g. 400,1500 3
require "fileutils"
require "open3"
require "rbconfig"
require "tmpdir"
require_relative "../spec/support/workspace_builder"

ROOT = File.expand_path("..", __dir__)
SIZES = ARGV.fetch(0, "400,1500").split(",").map { |size| Integer(size) }
RUNS = Integer(ARGV.fetch(1, "3"))

def generate(base, count)
  builder = WorkspaceBuilder.new(base, package_set: "bench.pkgs")
  builder.osdeps("boost:\n  ubuntu: libboost-all-dev\n  debian: libboost-all-dev\n")
  count.times do |i|
    # a layered graph: each package depends on up to three earlier ones
    dependencies = [i - 1, i / 2, i / 3].uniq.select { |d| d >= 0 && d < i }.map { |d| "pkg/p#{d}" }
    builder.package("pkg/p#{i}", type: :cmake, date: "2020-06-01T00:00:00Z", dependencies: dependencies,
                                 osdeps: i.even? ? ["boost"] : [], files: { "CMakeLists.txt" => "project(p#{i})\n" })
  end
  builder.layout("bench.pkgs")
  builder.create
end

# [seconds, peak RSS in MiB] of one run, measured by GNU time.
def measure(command)
  output, status = Open3.capture2e("/usr/bin/time", "-f", "@@ %e %M", *command)
  raise "failed: #{command.join(' ')}\n#{output}" unless status.success?

  seconds, kib = output[/@@ (\S+ \S+)/, 1].split
  [Float(seconds), Integer(kib) / 1024.0]
end

def median(runs)
  runs.sort_by(&:first)[runs.size / 2]
end

puts format("%-9s %12s %12s %12s %12s %10s", "packages", "relspec (s)", "autoproj (s)", "relspec MiB", "autoproj MiB",
            "overhead")
SIZES.each do |count|
  Dir.mktmpdir("relspec-bench-catalog") do |dir|
    workspace = generate(dir, count)
    out = File.join(dir, "catalog.yml")
    ours = median(Array.new(RUNS) do
      measure([RbConfig.ruby, File.join(ROOT, "exe", "relspec"), "catalog", "export", workspace, "--targets", "bionic",
               "--output", out])
    end)
    peer = median(Array.new(RUNS) { measure([RbConfig.ruby, File.join(ROOT, "bench", "autoproj_peer_load.rb"), workspace]) })
    puts format("%-9d %12.2f %12.2f %12.0f %12.0f %9.0f%%", count, ours[0], peer[0], ours[1], peer[1],
                ((ours[0] / peer[0]) - 1) * 100)
  end
end
puts "peak RSS of each whole process (GNU time)."
