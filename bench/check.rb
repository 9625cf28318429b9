# frozen_string_literal: true

# bench/check: the availability check (relspec check), in one run.
#
#   bundle exec ruby bench/check.rb
#
# 1. apt: 300 OS dependencies (relations of 100 packages) × 4 targets
#    against four generated archives of 60,000 binary packages each
#    (Provides and Architecture: all included), from a cold names cache
#    (every index parsed) and from the cached indices (target: < 0.5 s).
#    Peer: python3-apt's apt_pkg.TagFile reading the same four indices into
#    a set of names, then the same lookups.
# 2. Launchpad: the same relations against a local Launchpad-shaped server
#    (spec/support/launchpad_server.rb) answering each request after 5 ms.
#    relspec asks one question per distinct (name, series, arch), four at a
#    time; the peer is the seed's approach: one lookup per package and
#    dependency, one after the other, no cache.
require "digest"
require "fileutils"
require "open3"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec"
require "relspec/availability"
require "relspec/plan/target"
require_relative "../spec/support/launchpad_server"

RUNS = 5
INDEX_SIZE = 60_000
TARGETS = %w[jammy/amd64 jammy/arm64 noble/amd64 noble/arm64].map { |text| Relspec::Plan::Target.parse(text) }.freeze
PACKAGES = 100           # relspec packages of the release
PER_PACKAGE = 3          # OS relations each: 300 per target
DISTINCT = 120           # distinct Debian names among them

def debian_names
  Array.new(DISTINCT) { |i| "libdep#{i}-dev" }
end

# package name => its relations (names repeat across packages, as osdeps do)
def needs
  names = debian_names
  Array.new(PACKAGES) { |i| ["pkg/#{i}", Array.new(PER_PACKAGE) { |j| names[((i * 7) + (j * 31)) % DISTINCT] }] }.to_h
end

def requirements
  by_target = TARGETS.to_h do |target|
    relations = {}
    needs.each { |package, names| names.each { |name| (relations[name] ||= []) << package } }
    [target, relations]
  end
  Relspec::Availability::Requirements.new(by_target)
end

def packages_text(codename, arch)
  stanzas = Array.new(INDEX_SIZE) do |i|
    architecture = (i % 5).zero? ? "all" : arch
    provides = (i % 50).zero? ? "Provides: virtual#{i}\n" : ""
    "Package: pkg#{i}-#{codename}\nVersion: 1.#{i}-1\nArchitecture: #{architecture}\n#{provides}" \
      "Maintainer: Bench <bench@example.org>\nDescription: package #{i}\n"
  end
  deps = debian_names.map { |name| "Package: #{name}\nVersion: 1-1\nArchitecture: #{arch}\nDescription: dep\n" }
  (stanzas + deps).join("\n")
end

def write_archive(root)
  TARGETS.group_by(&:codename).each do |codename, targets|
    sums = targets.map do |target|
      path = "main/binary-#{target.arch}/Packages"
      FileUtils.mkdir_p(File.join(root, "dists", codename, File.dirname(path)))
      text = packages_text(codename, target.arch)
      File.write(File.join(root, "dists", codename, path), text)
      " #{Digest::SHA256.hexdigest(text)} #{text.bytesize} #{path}"
    end
    File.write(File.join(root, "dists", codename, "Release"),
               "Codename: #{codename}\nArchitectures: amd64 arm64\nComponents: main\nSHA256:\n#{sums.join("\n")}\n")
  end
end

# Answers Sources#for with one source for every target.
OneSource = Struct.new(:source) do
  def for(_target)
    [source, nil]
  end
end

def apt_check(root, cache_dir)
  reader = Relspec::Apt::Repository.new(Relspec::Apt::Fetcher.new(root), trusted: true)
  source = Relspec::Availability::AptSource.new(reader, ["main"], names_cache: Relspec::Apt::Cache.new(cache_dir))
  Relspec::Availability::Check.run("bench", requirements, OneSource.new(source))
end

PEER = <<~PY
  import apt_pkg, sys, time
  paths, wanted, runs = sys.argv[1].split(","), sys.argv[2].split(","), int(sys.argv[3])
  times = []
  for _ in range(runs):
      start = time.perf_counter()
      for path in paths:
          names = set()
          with apt_pkg.TagFile(path) as tagfile:
              for section in tagfile:
                  names.add(section["Package"])
                  provides = section.get("Provides")
                  if provides:
                      for relation in provides.split(","):
                          names.add(relation.strip().split(" ")[0])
          missing = [name for name in wanted if name not in names]
      times.append(time.perf_counter() - start)
  print(sorted(times)[runs // 2])
PY

def peer_seconds(root)
  paths = TARGETS.map { |target| File.join(root, "dists", target.codename, "main/binary-#{target.arch}/Packages") }
  out, status = Open3.capture2("/usr/bin/python3", "-c", PEER, paths.join(","), debian_names.join(","), RUNS.to_s)
  abort "python3-apt is needed for the peer (bin/setup installs it)" unless status.success?
  Float(out)
end

def launchpad_bench
  published = TARGETS.to_h { |target| [target.to_s, debian_names] }
  server = LaunchpadServer.new(published, delay: 0.005)
  cache = Dir.mktmpdir("relspec-bench-lp")
  client = Relspec::Availability::LaunchpadClient.new(base: server.base, timeout: 10)
  source = Relspec::Availability::LaunchpadSource.new(
    client: client, cache: Relspec::Availability::AnswerCache.new(cache)
  )
  ours = Timing.seconds { Relspec::Availability::Check.run("bench", requirements, OneSource.new(source)) }
  ours_requests = server.requests.size
  distinct = TARGETS.size * DISTINCT
  server.requests.clear
  again = Timing.seconds { Relspec::Availability::Check.run("bench", requirements, OneSource.new(source)) }
  again_requests = server.requests.size
  server.requests.clear
  seed = Relspec::Availability::LaunchpadClient.new(base: server.base, timeout: 10)
  sequential = Timing.seconds do
    TARGETS.each do |target|
      needs.each_value do |names|
        names.each { |name| seed.published_binaries(name, target.codename, target.arch) }
      end
    end
  end
  [ours, ours_requests, distinct, again, again_requests, sequential, server.requests.size]
ensure
  server&.stop
  FileUtils.rm_rf(cache) if cache
end

Dir.mktmpdir("relspec-bench-check") do |dir|
  root = File.join(dir, "archive")
  write_archive(root)
  relations = requirements.by_target.values.sum(&:size)
  occurrences = TARGETS.size * PACKAGES * PER_PACKAGE
  cold = Timing.median(RUNS) do
    cache = Dir.mktmpdir("names", dir)
    apt_check(root, cache)
  ensure
    FileUtils.rm_rf(cache)
  end
  warm_cache = File.join(dir, "warm")
  report = apt_check(root, warm_cache)
  abort "bench: expected nothing missing, got #{report.missing.size}" unless report.missing.empty?
  warm = Timing.median(RUNS) { apt_check(root, warm_cache) }
  peer = peer_seconds(root)
  puts "apt: #{occurrences} relations of #{PACKAGES} packages on #{TARGETS.size} targets (#{relations} distinct " \
       "(name, target)), #{INDEX_SIZE + DISTINCT} packages per index, median of #{RUNS}"
  puts format("  %-42s %8.3f s  %5.2fx apt_pkg", "relspec, cold (every index parsed)", cold, cold / peer)
  puts format("  %-42s %8.3f s  %5.2fx apt_pkg   (target < 0.5 s)", "relspec, cached indices", warm, warm / peer)
  puts format("  %-42s %8.3f s", "peer: python3-apt TagFile + set lookups", peer)

  ours, ours_requests, distinct, again, again_requests, sequential, seed_requests = launchpad_bench
  puts "launchpad: the same relations, server answering after 5 ms per request"
  puts format("  %-42s %8.3f s  %5d requests (distinct (name, series, arch): %d)", "relspec, 4 concurrent, cold cache",
              ours, ours_requests, distinct)
  puts format("  %-42s %8.3f s  %5d requests", "relspec, again within the TTL", again, again_requests)
  puts format("  %-42s %8.3f s  %5d requests  (relspec: %.2fx the time, %.2fx the requests)",
              "peer: one lookup per package, sequential", sequential, seed_requests, ours / sequential,
              ours_requests.to_f / seed_requests)
end
