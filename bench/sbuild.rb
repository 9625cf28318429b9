# frozen_string_literal: true

# bench/sbuild: the per-package cost of the sbuild backend (clean unshare
# chroot) against the host backend, on the same small package, in one run,
# and where an sbuild build's time goes.
#
# 1. relspec build --backend host, then --backend sbuild (as a user runs it:
#    the chroot on tmpfs when there is room, apt's lists in the tarball,
#    dpkg without fsync): each package's recorded duration, and the ratio.
# 2. The backend's own sbuild command line (from the build's log) run again
#    three ways, each line of its output timestamped: as the backend runs it
#    now; with the chroot unpacked on disk (no SBUILD_CONFIG); and on a
#    tarball made as relspec made it before issue 32 (no lists, fsync), on
#    disk. Each row gives sbuild's phases (its section banners).
#
# The chroot tarball lives in relspec's cache (XDG_CACHE_HOME): made by the
# first --prepare when missing, and timed separately then. The tarball of
# the "before" row is made in a temporary folder by this bench.
#
#   bundle exec ruby bench/sbuild.rb
require "open3"
require "rbconfig"
require "tmpdir"
require "yaml"
require_relative "timing"
require_relative "../spec/support/build_release"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec/builder/chroot"
require "relspec/builder/unpack_dir"

PHASES = [["start", nil], ["unpack chroot", /^Unpacking \S+ to /], ["apt-get update", /^\| Update chroot/],
          ["copy source", /^\| Fetch source files/], ["build-deps", /^\| Install package build dependencies/],
          ["build", /^\| Check architectures/], ["changes etc.", /^\| Changes/], ["clean up", /^\| Post Build/],
          ["end", /^\| Summary/]].freeze

def relspec(dir, *args)
  Timing.seconds do
    output, status = Open3.capture2e(RbConfig.ruby, BuildRelease::EXE, *args, chdir: dir)
    raise "relspec #{args.first} failed:\n#{output}" unless status.success?
  end
end

def duration(release)
  records = YAML.safe_load(File.read(File.join(release.target_dir, "build-results.yml"))).fetch("packages")
  records.values.first.fetch("duration")
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

def row(label, total, phases)
  parts = phases.map { |name, seconds| format("%s %.1f", name, seconds) }
  puts format("  %-34s %6.1f s: %s", label, total, parts.join(", "))
end

Dir.mktmpdir("relspec-bench-sbuild") do |dir|
  release = BuildRelease.new(dir, "sbench")
  release.package("base/small")
  release.compile
  build = %w[build specs/sbench.yml --out out --quiet --rebuild --backend]
  prepare = relspec(dir, "build", "specs/sbench.yml", "--out", "out", "--quiet", "--prepare")
  relspec(dir, *build, "host")
  host = duration(release)
  relspec(dir, *build, "sbuild")
  sbuild = duration(release)

  puts format("first --prepare             %6.1f s (makes the chroot unless the cache has it)", prepare)
  puts format("host backend, one package   %6.1f s", host)
  puts format("sbuild, same package        %6.1f s  (overhead %.1f s per package, ratio %.1f)", sbuild,
              sbuild - host, sbuild / host)

  log = File.read(File.join(release.target_dir, "logs", "#{release.source('base/small')}.log"))
  command = log.lines.first.delete_prefix("$ ").split
  unpack_dir = Relspec::Builder::UnpackDir.new
  tmpfs = unpack_dir.environment
  puts "sbuild alone, its phases (seconds):"
  row("now#{tmpfs.empty? ? ' (no room on tmpfs)' : ', chroot on tmpfs'}", *timed_sbuild(command, tmpfs))
  unpack_dir.close
  row("now, chroot on disk", *timed_sbuild(command, {}))

  old = File.join(dir, "before.tar.zst")
  sources = Relspec::Builder::Chroot.host_sources
  made = Timing.seconds do
    output, status = Open3.capture2e("mmdebstrap", "--variant=buildd", "--mode=unshare", "--arch=amd64",
                                     "--include=debhelper", "bookworm", old, *sources)
    raise "mmdebstrap failed:\n#{output}" unless status.success?
  end
  before = command.map { |word| word.start_with?("--chroot=") ? "--chroot=#{old}" : word }
  row("before: no lists, fsync, on disk", *timed_sbuild(before, {}))
  puts format("  (that tarball made in %.1f s)", made)
end
