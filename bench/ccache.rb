# frozen_string_literal: true

# bench/ccache: what the compiler cache bound into sbuild's chroots
# (Relspec::Builder::Ccache) saves when a change rebuilds a real C++
# package and its reverse dependencies, in one run:
#
# 1. the real Rock layout's workspace from ../shared (ToolchainRelease, as
#    bin/toolchain makes it) with the selection, compiled, and built with
#    sbuild into an empty ccache folder: the cold builds;
# 2. a commit on the changed package's checkout (its README: no C++
#    changes) and compile again: the package and everything that depends on
#    it get new versions, built in other folders, as after a blacklist or
#    pin change; built with sbuild again: the warm builds.
#
# It prints each rebuilt package's cold and warm build time (relspec's
# recorded durations), their sums, the ratio warm/cold (issue 32's target:
# at most 0.5) and ccache's counters of the warm run. Runs as root (only
# root's builds have a ccache). The chroot tarball is relspec's cache's
# (XDG_CACHE_HOME); the ccache folder is the bench's own.
#
#   bundle exec ruby bench/ccache.rb [--select base/types,base/numeric] [--change base/types] [--jobs 2] [--keep DIR]
require "fileutils"
require "open3"
require "optparse"
require "rbconfig"
require "time"
require "tmpdir"
require "yaml"
require_relative "timing"
require_relative "../spec/support/toolchain_release"

EXE = File.expand_path("../exe/relspec", __dir__)

# base/types and its reverse dependencies that ../shared bundles and the
# toolchain release builds (base/orogen/types also needs external/sisl)
DEFAULT_SELECTION = %w[base/types base/numeric].freeze

options = { select: DEFAULT_SELECTION, change: "base/types", jobs: 2, keep: nil }
OptionParser.new do |parser|
  parser.banner = "usage: bench/ccache.rb [--select a,b] [--change PACKAGE] [--jobs N] [--keep DIR]"
  parser.on("--select LIST", Array, "the release's selection (default #{DEFAULT_SELECTION.join(',')})") do |list|
    options[:select] = list
  end
  parser.on("--change PACKAGE", "the package whose source changes (default base/types)") { |name| options[:change] = name }
  parser.on("--jobs N", Integer) { |jobs| options[:jobs] = jobs }
  parser.on("--keep DIR", "work in DIR and keep it (default: a temporary folder, removed)") { |dir| options[:keep] = dir }
end.parse!
abort "bench/ccache: #{RealRockWorkspace.skip_reason}" unless RealRockWorkspace.available?
abort "bench/ccache: runs as root (only root's sbuild builds have a ccache)" unless Process.uid.zero?

def run!(dir, env, *command)
  output, status = Open3.capture2e(env, *command, chdir: dir)
  raise "#{command.join(' ')} failed:\n#{output}" unless status.success?

  output
end

# build-results.yml's built records: source => [version, duration].
def built(release)
  records = YAML.safe_load_file(File.join(release.target_dir, "build-results.yml")).fetch("packages")
  records.select { |_, record| record["status"] == "built" }.transform_values { |r| [r["version"], r["duration"]] }
end

def ccache_stats(folder)
  run!("/", {}, "ccache", "--dir", folder, "--print-stats").lines.to_h do |line|
    name, value = line.split("\t")
    [name, value.to_i]
  end
end

# compile, then build with sbuild (+more+: more options of build).
def phase(release, env, jobs, *more)
  relspec = [RbConfig.ruby, EXE]
  run!(release.dir, env, *relspec, "compile", "specs/rock.yml", "--out", "out", "--quiet")
  seconds = Timing.seconds do
    run!(release.dir, env, *relspec, "build", "specs/rock.yml", "--out", "out", "--quiet", "--backend", "sbuild",
         "--jobs", jobs.to_s, *more)
  end
  [built(release), seconds]
end

work = options[:keep] || Dir.mktmpdir("relspec-bench-ccache")
begin
  FileUtils.mkdir_p(work)
  release = ToolchainRelease.new(File.expand_path(work), select: options[:select])
  release.write
  # the cache of this bench only, empty: reachable by the chroot's build user
  # (relspec gives it to that uid), so not in a closed temporary folder
  ccache = File.join(work, "ccache")
  FileUtils.rm_rf(ccache)
  File.chmod(0o755, work)
  env = { "RELSPEC_CCACHE" => ccache }

  # everything, also what a kept DIR's earlier run built
  cold, cold_seconds = phase(release, env, options[:jobs], "--rebuild")
  before = ccache_stats(ccache)
  checkout = release.workspace.source_dir(options[:change])
  File.write(File.join(checkout, "README.relspec-bench"), "a change that compiles nothing\n")
  run!(checkout, {}, "git", "add", "README.relspec-bench")
  run!(checkout, { "GIT_AUTHOR_DATE" => Time.now.utc.iso8601, "GIT_COMMITTER_DATE" => Time.now.utc.iso8601 },
       "git", "-c", "user.name=bench", "-c", "user.email=bench@relspec.invalid", "commit", "-q", "-m", "bench")
  warm, warm_seconds = phase(release, env, options[:jobs])
  after = ccache_stats(ccache)

  rebuilt = warm.keys.select { |source| cold.key?(source) && cold[source].first != warm[source].first }
  raise "the change rebuilt nothing at a new version (built: #{warm.keys.join(', ')})" if rebuilt.empty?

  puts "selection #{options[:select].join(',')}, changed #{options[:change]}, --jobs #{options[:jobs]}"
  puts format("cold run (everything, empty ccache): %.1f s; warm run (the rebuilt packages): %.1f s",
              cold_seconds, warm_seconds)
  rebuilt.sort.each do |source|
    puts format("  %-40s cold %7.1f s  warm %7.1f s", source, cold[source].last, warm[source].last)
  end
  cold_sum = rebuilt.sum { |source| cold[source].last }
  warm_sum = rebuilt.sum { |source| warm[source].last }
  puts format("rebuilt packages: cold %.1f s, warm %.1f s, ratio warm/cold %.2f (target <= 0.5)",
              cold_sum, warm_sum, warm_sum / cold_sum)
  hits = %w[direct_cache_hit preprocessed_cache_hit].sum { |key| after.fetch(key, 0) - before.fetch(key, 0) }
  misses = after.fetch("cache_miss", 0) - before.fetch("cache_miss", 0)
  puts "ccache in the warm run: #{hits} hits, #{misses} misses (cold run: #{before.fetch('cache_miss', 0)} misses)"
ensure
  FileUtils.rm_rf(work) unless options[:keep]
end
