# frozen_string_literal: true

# bench/sbuild_release: the demo's two releases (bin/demo's specs: demo-base,
# then demo-child on what demo-base published; bookworm and trixie) built in
# sbuild the old way and the new way, one after the other on this machine
# (issue 48). Old way: RELSPEC_CHROOT_LAYERS=off RELSPEC_APT_CACHE=off (the
# chroot tarball unpacked in every build, apt-get update and every
# build-dependency downloaded in every build). New way: the chroot unpacked
# once per run and target, a throw-away layer per build, its lists refreshed
# once, the downloads kept in an apt cache that starts empty (this bench's).
# Both without ccache, so that the second way gets no compiler hits from the
# first.
#
# The example workspace and specs are copied from this checkout's HEAD into a
# temporary folder; relspec is this checkout's. Each release is compiled once
# and built with --rebuild --jobs 2 both ways (old first), then published (the
# child plans against it). Prints wall time per build run, the sum of the
# packages' recorded durations per target, and the load average.
#
#   bundle exec ruby bench/sbuild_release.rb
#
# BENCH_CORE_SLICE=1: a slice of the Rock core instead (11 packages; issue
# 48): the real buildconf's offline workspace (RockCoreRelease, from
# ../shared's bundles), bookworm/amd64 only, selecting SLICE with what they
# depend on (tools/class_loader with base/console_bridge, base/logging and
# base/cmake: CMake; tools/metaruby with utilrb and facets,
# base/templates/ruby_lib with hoe-yard, rake-compiler and rice: Ruby), built old
# way then new way; not published.
require "fileutils"
require "open3"
require "rbconfig"
require "tmpdir"
require "yaml"
require_relative "timing"

ROOT = File.expand_path("..", __dir__)
EXE = File.join(ROOT, "exe", "relspec")
RELEASES = %w[demo-base demo-child].freeze
SLICE = %w[tools/class_loader tools/metaruby base/templates/ruby_lib].freeze

def run!(env, *command, chdir:)
  output, status = Open3.capture2e(env, *command, chdir: chdir)
  raise "#{command.join(' ')} failed:\n#{output}" unless status.success?

  output
end

def relspec(dir, *args, env: {})
  run!(env, RbConfig.ruby, EXE, *args, chdir: dir)
end

# A build run: its wall time; a failed package is counted, not fatal (its
# log stays in the bench's folder, which is then kept).
def build(dir, spec, env)
  status = nil
  seconds = Timing.seconds do
    _output, status = Open3.capture2e(env, RbConfig.ruby, EXE, "build", spec, "--backend", "sbuild", "--jobs", "2",
                                      "--rebuild", "--quiet", chdir: dir)
  end
  [seconds, status.success?]
end

def load_average
  File.read("/proc/loadavg").split.first(3).join(" ")
end

# The recorded builds of the release: target => [built, failed, sum of durations].
def durations(dir, release)
  Dir.glob(File.join(dir, "build", release, "*", "build-results.yml")).sort.to_h do |file|
    records = YAML.safe_load(File.read(file)).fetch("packages").values
    built = records.count { |record| record["status"] == "built" }
    [File.basename(File.dirname(file)), [built, records.size - built, records.sum { |record| record.fetch("duration") }]]
  end
end

# The demo's workspace and specs, from this checkout's HEAD, in +dir+;
# [folder, releases].
def demo(dir)
  demo = File.join(dir, "demo")
  FileUtils.mkdir_p(demo)
  run!({}, "sh", "-c", "git -C \"$1\" archive HEAD examples specs spec/support spec/fixtures | tar -x -C \"$2\"",
       "sh", ROOT, demo, chdir: dir)
  run!({}, RbConfig.ruby, File.join(demo, "examples", "create-workspace"), chdir: demo)
  [demo, RELEASES]
end

# The Rock core's workspace and a spec of SLICE in +dir+; [folder, releases].
def core_slice(dir)
  require_relative "../spec/support/rock_core_workspace"
  raise "the real package sets are not in #{FixtureWorkspace::BUNDLES}" unless RockCoreWorkspace.available?

  release = RockCoreRelease.new(File.join(dir, "rock-core"), targets: ["bookworm/amd64"])
  release.write
  text = release.spec_text
  raise "RockCoreRelease selects no longer rock.core" unless text.include?("select: [rock.core]")

  File.write(release.spec_path, text.sub("select: [rock.core]", "select: [#{SLICE.join(', ')}]"))
  [release.dir, ["rock-core"]]
end

$stdout.sync = true
dir = Dir.mktmpdir("relspec-bench-sbuild-release")
failed = false
begin
  slice = ENV["BENCH_CORE_SLICE"] == "1"
  folder, releases = slice ? core_slice(dir) : demo(dir)
  # the chroot's root must reach the apt cache (relspec makes its folder its own)
  File.chmod(0o755, dir)
  ways = { "old" => { "RELSPEC_CHROOT_LAYERS" => "off", "RELSPEC_APT_CACHE" => "off", "RELSPEC_CCACHE" => "off" },
           "new" => { "RELSPEC_APT_CACHE" => File.join(dir, "apt"), "RELSPEC_CCACHE" => "off" } }
  totals = Hash.new(0.0)
  releases.each do |release|
    spec = "specs/#{release}.yml"
    relspec(folder, "plan", spec)
    relspec(folder, "compile", spec, "--no-check")
    ways.each do |way, env|
      load = load_average
      seconds, success = build(folder, spec, env)
      failed ||= !success
      totals[way] += seconds
      per_target = durations(folder, release).map do |target, (built, failures, sum)|
        format("%s %d built %d failed %.1f s", target, built, failures, sum)
      end
      puts format("%-10s %s way: %6.1f s wall (load %s before); build durations: %s", release, way, seconds, load,
                  per_target.join(", "))
    end
    relspec(folder, "publish", spec) unless slice
  end
  puts format("all builds: old way %.1f s, new way %.1f s (%.0f %% less), load %s at the end", totals["old"],
              totals["new"], 100 * (1 - (totals["new"] / totals["old"])), load_average)
ensure
  # a failed build's log is worth reading
  failed ? puts("kept #{dir} (a build failed)") : FileUtils.rm_rf(dir)
end
