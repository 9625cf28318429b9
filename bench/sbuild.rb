# frozen_string_literal: true

# bench/sbuild: the per-package cost of the sbuild backend (clean unshare
# chroot) against the host backend, on the same small packages, in one run,
# before and after issue 48, and where an sbuild build's time goes.
#
# 1. relspec build of two small packages with --backend host, then with
#    --backend sbuild the old way (RELSPEC_CHROOT_LAYERS=off and
#    RELSPEC_APT_CACHE=off: the tarball unpacked in every build, every
#    build-dependency downloaded) and the new way (the chroot unpacked once
#    per run, a throw-away overlay layer per build, downloads kept per
#    target), alternating BENCH_ROUNDS times (default 2), and the new way
#    without the build-dependency layers (RELSPEC_DEPENDENCY_LAYERS=off;
#    the two packages declare the same Build-Depends, so with them the
#    second builds on the first's layer, and both with sbuild's null
#    resolver): each package's recorded duration and the sbuild/host ratio.
# 2. sbuild alone, each line of its output timestamped, its phases (its
#    section banners) in a table with the total's ratio to the host
#    backend: the old command line as the backend ran it, then the same
#    build on a layer over the chroot unpacked once (ChrootLayers, with its
#    configuration: no apt-get update, nothing purged), without and with
#    the kept .debs, and on a layer over the build-dependency layer of its
#    exact set (DependencyLayers; resolving the set, and making the layer
#    the first time, timed apart), alternating as well; where the chroot
#    then holds exactly the build's set, the same with sbuild's null
#    resolver (no dummy package, nothing installed), as the backend runs it.
#
# The chroot tarball lives in relspec's cache (XDG_CACHE_HOME): made by the
# first --prepare when missing, and timed separately then. The layers need
# root (mounting an overlay); as another user the new way is the old one.
#
#   bundle exec ruby bench/sbuild.rb
#   BENCH_CMAKE=1 BENCH_ROUNDS=1 bundle exec ruby bench/sbuild.rb   (packages with a build-dependency set)
require "open3"
require "rbconfig"
require "tmpdir"
require "yaml"
require_relative "timing"
require_relative "../spec/support/build_release"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/builder/apt_cache"
require "relspec/builder/chroot"
require "relspec/builder/chroot_layers"
require "relspec/builder/dependency_layers"
require "relspec/builder/request"
require "relspec/builder/sbuild_backend"
require "relspec/builder/tool"
require "relspec/builder/unpack_dir"
require "relspec/target"

PHASES = [["start", nil], ["unpack + session setup", /^Unpacking \S+ to /], ["apt-get update", /^\| Update chroot/],
          ["copy source", /^\| Fetch source files/], ["build-deps", /^\| Install package build dependencies/],
          ["build", /^\| Check architectures/], ["changes etc.", /^\| Changes/], ["clean up", /^\| Post Build/],
          ["end", /^\| Summary/]].freeze

def relspec(dir, *args, env: {})
  Timing.seconds do
    output, status = Open3.capture2e(env, RbConfig.ruby, BuildRelease::EXE, *args, chdir: dir)
    raise "relspec #{args.first} failed:\n#{output}" unless status.success?
  end
end

# Each package's recorded duration, in build order.
def durations(release, packages)
  records = YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml"))).fetch("packages")
  packages.map { |package| records.fetch(release.source(package)).fetch("duration") }
end

# Runs +command+ in a fresh folder, timestamping each output line; returns
# [total seconds, {phase => seconds}].
def timed_sbuild(command, env)
  Dir.mktmpdir("relspec-bench-sbuild-run") do |work|
    command = command.map { |word| word.start_with?("--build-dir=") ? "--build-dir=#{work}" : word }
    started = Process.clock_gettime(Process::CLOCK_MONOTONIC)
    marks = { "start" => 0.0 }
    Open3.popen2e(env, *command, chdir: work) do |_in, out, wait|
      out.each_line do |line|
        phase = PHASES.find { |_name, pattern| pattern&.match?(line) }
        marks[phase.first] ||= Process.clock_gettime(Process::CLOCK_MONOTONIC) - started if phase
      end
      raise "sbuild failed: #{command.join(' ')}" unless wait.value.success?
    end
    total = Process.clock_gettime(Process::CLOCK_MONOTONIC) - started
    marks["end"] = total
    names = PHASES.map(&:first).select { |name| marks[name] }
    [total, names.each_cons(2).to_h { |from, to| [from, marks[to] - marks[from]] }]
  end
end

# One row of the phase table: every phase's seconds ("-" for a step this
# way leaves out), the total and its ratio to the host backend's build.
def row(label, host, total, phases)
  cells = PHASES.map(&:first)[0..-2].map { |name| phases[name] ? format("%.1f", phases[name]) : "-" }
  puts format("| %s | %.1f | %.1f | %s |", label, total, total / host, cells.join(" | "))
end

def header
  puts "| row | total | ratio to host | #{PHASES.map(&:first)[0..-2].join(' | ')} |"
end

# The sbuild command line the backend ran for +package+ the old way.
def old_command(release, package)
  log = File.read(File.join(release.target_dir, "logs", "#{release.source(package)}.log"))
  log.lines.find { |line| line.start_with?("$ sbuild ") }.delete_prefix("$ ").split
end

# Runs +command+ (an sbuild command line) the new way: on a layer over the
# chroot unpacked once into +layers+, with the apt download cache when +apt+.
def timed_layered(command, layers, lower, unpack_dir, apt)
  target = Relspec::Target.new("bookworm", "amd64")
  layers.layer do |upper, work, merged|
    sbuild = command.map { |word| word.start_with?("--chroot=") ? "--chroot=#{layers.empty_tarball}" : word }
    env = unpack_dir.environment([*layers.config_lines(merged), *apt&.config_lines(target)])
    timed_sbuild(layers.wrap(sbuild, lower, upper, work, merged), env)
  end
end

# +command+ as the backend runs it when the chroot holds the exact set
# (SbuildBackend#command's installed: true): sbuild's null resolver, no
# .debs to resolve from.
def null_command(command)
  [*command[0..-2].grep_v(/\A--extra-(package|repository)/), "--build-dep-resolver=null", command.last]
end

def report(label, host, times)
  puts format("  %-46s %s", label, times.map { |time| format("%5.1f s (ratio %4.1f)", time, time / host) }.join(", "))
end

def load_average
  File.read("/proc/loadavg").split.first(3).join(" ")
end

PACKAGES = %w[base/small base/small2].freeze
OLD = { "RELSPEC_CHROOT_LAYERS" => "off", "RELSPEC_APT_CACHE" => "off" }.freeze
NO_DEPENDENCY_LAYERS = { "RELSPEC_DEPENDENCY_LAYERS" => "off" }.freeze
# old and new alternate, this many times each: the load of a shared machine
# moves within a run
ROUNDS = Integer(ENV.fetch("BENCH_ROUNDS", "2"), 10)

Dir.mktmpdir("relspec-bench-sbuild") do |dir|
  release = BuildRelease.new(dir, "sbench")
  # BENCH_CMAKE=1: two CMake packages instead, whose build-dependencies
  # (cmake, ruby-dev: 40 packages) are not in the chroot
  cmake = { cmake: "enable_language(CXX)\nadd_executable(hello hello.cpp)",
            files: { "hello.cpp" => "int main() { return 0; }\n" } }
  PACKAGES.each { |package| release.package(package, **(ENV["BENCH_CMAKE"] == "1" ? cmake : {})) }
  release.compile
  build = %w[build specs/sbench.yml --out out --quiet --rebuild --jobs 1 --backend]
  prepare = relspec(dir, "build", "specs/sbench.yml", "--out", "out", "--quiet", "--prepare")
  puts format("first --prepare %.1f s (makes the chroot unless the cache has it)", prepare)
  puts format("per package (%s), relspec build's recorded durations:", PACKAGES.join(", "))
  command = nil
  host = nil
  ROUNDS.times do |round|
    puts format(" round %d, load average %s", round + 1, load_average)
    relspec(dir, *build, "host")
    host = durations(release, PACKAGES).sum / PACKAGES.size.to_f
    relspec(dir, *build, "sbuild", env: OLD)
    before = durations(release, PACKAGES)
    command ||= old_command(release, PACKAGES.first)
    relspec(dir, *build, "sbuild", env: NO_DEPENDENCY_LAYERS)
    layered = durations(release, PACKAGES)
    relspec(dir, *build, "sbuild")
    after = durations(release, PACKAGES)
    report("host backend", host, [host])
    report("sbuild before: tarball per build, no kept .debs", host, before)
    report("sbuild layers (one unpack per run), kept .debs", host, layered)
    report("sbuild after: + build-dependency layers, null resolver", host, after)
  end

  unpack_dir = Relspec::Builder::UnpackDir.new
  tmpfs = unpack_dir.environment
  ids = Relspec::Builder::SbuildBackend.layer_ids
  unless ids
    puts "sbuild alone: the layers need root, not timed"
    next
  end
  tarball = command.find { |word| word.start_with?("--chroot=") }.delete_prefix("--chroot=")
  layers = Relspec::Builder::ChrootLayers.new(tarball, unpack_dir.folder("bench"), uids: ids[0], gids: ids[1])
  lower = nil
  unpacked = Timing.seconds { lower = layers.lower(Relspec::Builder::Tool.new, "bench", File.join(dir, "unpack.log")) }
  apt = Relspec::Builder::AptCache.from_environment
  puts format("sbuild alone, its phases (seconds; the chroot unpacked and its lists refreshed once in %.1f s; " \
              "ratio to the last host build, %.1f s):", unpacked, host)
  target = Relspec::Target.new("bookworm", "amd64")
  dependency_layers = Relspec::Builder::DependencyLayers.new(layers.folder, namespace: layers.namespace, arch: "amd64",
                                                                            owner: [ids[0].first, ids[1].first],
                                                                            archives: apt&.target_folder(target))
  request = Relspec::Builder::Request.new(source: "bench", dsc: command.last, target: target, repositories: [],
                                          local_debs: [], log: File.join(dir, "deps.log"))
  ROUNDS.times do |round|
    puts format(" round %d, load average %s", round + 1, load_average)
    header
    row("before#{tmpfs.empty? ? ' (no room on tmpfs)' : ', chroot on tmpfs'}", host, *timed_sbuild(command, tmpfs))
    row("after: layer", host, *timed_layered(command, layers, lower, unpack_dir, nil))
    row("after: layer, kept .debs", host, *timed_layered(command, layers, lower, unpack_dir, apt)) if apt
    installed = nil
    resolved = Timing.seconds { installed = dependency_layers.for(Relspec::Builder::Tool.new, request, lower) }
    unless installed
      puts format("| after: build-dependency layer: none, sbuild resolves (resolved in %.1f s; %s) |", resolved,
                  File.read(request.log).lines.grep(/^relspec: /).last&.chomp)
      next
    end

    what = installed.folder ? "build-dependency layer" : "no build-dependency layer (none to install)"
    under = installed.folder ? "#{installed.folder}:#{lower}" : lower
    label = format("after: %s (resolved%s in %.1f s)", what, round.zero? && installed.folder ? " and made" : "", resolved)
    row("#{label}, apt resolver", host, *timed_layered(command, layers, under, unpack_dir, apt))
    next unless installed.complete

    row("#{label}, null resolver", host, *timed_layered(null_command(command), layers, under, unpack_dir, nil))
  end
  unpack_dir.close
end
