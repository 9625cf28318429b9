# frozen_string_literal: true

# bench/build: `relspec build --backend host --jobs 2` of a generated release
# of small real packages (import packages, each really built by
# dpkg-buildpackage) in a layered dependency graph, against the lower bound
# max(critical path, total build time / jobs) computed from the durations
# the run itself recorded in build-results.yml (target ≤ 1.15). The peer is
# the same release built again with --jobs 1 (serial), in the same run.
# Last, a build with nothing to do (everything recorded as built), against
# `relspec show` of the same spec (starting relspec and reading the spec).
#
# With --engine slurm, the same release is built on a real one-node Slurm
# cluster (spec/support/slurm_cluster.rb, 2 CPUs: two jobs at once) and its
# ratio to its own lower bound is printed beside the local scheduler's, with
# the per-job overhead of each: (wall × 2 − sum of durations) / packages.
#
#   bundle exec ruby bench/build.rb [PACKAGES] [LAYERS] [--engine slurm]
require "fileutils"
require "open3"
require "rbconfig"
require "tmpdir"
require "yaml"
require_relative "timing"
require_relative "../spec/support/build_release"

SLURM = ARGV.each_cons(2).include?(%w[--engine slurm])
NUMBERS = ARGV.reject { |arg| arg.start_with?("--") || arg == "slurm" }
COUNT = Integer(NUMBERS.fetch(0, "30"))
LAYERS = Integer(NUMBERS.fetch(1, "5"))
JOBS = 2

def relspec(dir, *args)
  Timing.seconds do
    output, status = Open3.capture2e(RbConfig.ruby, BuildRelease::EXE, *args, chdir: dir)
    raise "relspec #{args.first} failed:\n#{output}" unless status.success?
  end
end

def build(dir, *args)
  relspec(dir, "build", "specs/bench.yml", "--out", "out", "--backend", "host", "--quiet", *args)
end

# Longest chain of recorded durations through the build-dependencies.
def critical_path(plan, durations)
  finish = {}
  plan.fetch("builds").each do |entry|
    start = entry.fetch("build_depends").map { |dep| finish.fetch(dep) }.max || 0
    finish[entry.fetch("source")] = start + durations.fetch(entry.fetch("source"))
  end
  finish.values.max
end

# [wall, sum of durations, lower bound] of a build just finished.
def measured(release, plan, wall)
  records = YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml"))).fetch("packages")
  durations = records.transform_values { |record| record.fetch("duration") }
  total = durations.values.sum
  [wall, total, [critical_path(plan, durations), total / JOBS].max]
end

def slurm_comparison(dir, release, plan)
  require "json"
  require_relative "../spec/support/cli_runner"
  require_relative "../spec/support/slurm_cluster"
  cluster = SlurmCluster.start(cpus: JOBS)
  begin
    local = measured(release, plan, build(dir, "--jobs", JOBS.to_s, "--rebuild"))
    wall = Timing.seconds do
      run = cluster.relspec("build", "specs/bench.yml", "--out", "out", "--backend", "host", "--engine", "slurm",
                            "--rebuild", "--quiet", "--slurm", "poll_interval=1", chdir: dir)
      raise "relspec build --engine slurm failed:\n#{run.stdout}#{run.stderr}" unless run.status.success?
    end
    slurm = measured(release, plan, wall)
  ensure
    cluster.stop
  end
  puts format("%d packages, %d layers, host backend, 2 at once", COUNT, LAYERS)
  puts "engine   wall      sum of durations  lower bound  ratio  overhead per job"
  { "local" => local, "slurm" => slurm }.each do |name, (w, total, bound)|
    puts format("%-6s %7.1f s %11.1f s %12.1f s %6.2f %9.2f s", name, w, total, bound, w / bound,
                (w * JOBS - total) / COUNT)
  end
  puts "(target: slurm ratio <= 1.3)"
end

Dir.mktmpdir("relspec-bench-build") do |dir|
  release = BuildRelease.new(dir, "bench")
  per_layer = (COUNT.to_f / LAYERS).ceil
  names = Array.new(COUNT) { |i| format("layer%d/pkg%02d", i / per_layer, i) }
  names.each_with_index do |name, i|
    layer = i / per_layer
    previous = layer.zero? ? [] : names[((layer - 1) * per_layer)...(layer * per_layer)]
    # One or two dependencies on the layer below, spread deterministically.
    deps = previous.empty? ? [] : [previous[i % previous.size], previous[((i * 7) + 3) % previous.size]].uniq
    release.package(name, dependencies: deps)
  end
  release.compile
  plan = YAML.safe_load(File.read(File.join(release.target_dir, "plan.yml")))
  next slurm_comparison(dir, release, plan) if SLURM

  wall = build(dir, "--jobs", JOBS.to_s)
  records = YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml"))).fetch("packages")
  durations = records.transform_values { |record| record.fetch("duration") }
  total = durations.values.sum
  path = critical_path(plan, durations)
  bound = [path, total / JOBS].max
  serial = build(dir, "--jobs", "1", "--rebuild")
  idle = Timing.median(3) { build(dir, "--jobs", JOBS.to_s) }
  # The peer of a build with nothing to do: relspec starting and reading the
  # spec hierarchy (`relspec show`), on the same loaded machine.
  show = Timing.median(3) { relspec(dir, "show", "specs/bench.yml") }

  puts format("%d packages, %d layers, host backend", COUNT, LAYERS)
  puts format("--jobs %d wall time          %7.1f s", JOBS, wall)
  puts format("  sum of recorded durations  %7.1f s (/ %d = %.1f s)", total, JOBS, total / JOBS)
  puts format("  critical path              %7.1f s", path)
  puts format("  lower bound                %7.1f s", bound)
  puts format("  ratio wall / lower bound   %7.2f   (target <= 1.15)", wall / bound)
  puts format("--jobs 1 (serial peer)       %7.1f s   (ratio serial / --jobs %d: %.2f)", serial, JOBS, serial / wall)
  puts format("nothing to do                %7.2f s   (relspec show: %.2f s, ratio %.2f)", idle, show, idle / show)
end
