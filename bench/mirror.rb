# frozen_string_literal: true

# bench/mirror: the field mirror of the demo release (relspec mirror), in
# one run on one machine.
#
#   RELSPEC_DEMO_BACKEND=host bin/demo   # once: publishes demo-base and demo-child
#   bundle exec ruby bench/mirror.rb
#
# 1. Time to compute demo-child's closure for bookworm/amd64 (its seven
#    packages, the minimal system, every alternative and provider followed),
#    reading the two release repositories and this machine's Debian lists.
#    Peer: `apt-get install --simulate` of the same names with a private
#    configuration and an empty dpkg status (apt's own resolver, which picks
#    one alternative each), its lists updated before the timing.
# 2. The mirror's size against a whole-component mirror of the same
#    components (what apt-mirror copies: every package of bookworm,
#    bookworm-updates and bookworm-security main for amd64, and the two
#    release repositories).
require "fileutils"
require "open3"
require "tmpdir"
require_relative "timing"
$LOAD_PATH.unshift(File.expand_path("../lib", __dir__))
require "relspec"
require "relspec/mirror"

RUNS = 3
ROOT = File.expand_path("..", __dir__)
SPEC = File.join(ROOT, "specs", "demo-child.yml")
TARGET = Relspec::Target.parse("bookworm/amd64")
REPOSITORIES = %w[demo-base demo-child].map { |name| File.join(ROOT, "build", "repositories", name) }

abort "bench/mirror: run `RELSPEC_DEMO_BACKEND=host bin/demo` first" unless REPOSITORIES.all? { |dir| File.directory?(File.join(dir, "dists")) }

resolution = Relspec::ReleaseSpec.resolve(SPEC)
closure = nil
read = nil
relspec_time = Timing.median(RUNS) do
  read = Relspec::Mirror::Sources.new(resolution).read(TARGET)
  closure = Relspec::Mirror::Closure.of(read.index, read.seeds)
  closure.add(read.required, "the minimal system")
end
names = read.seeds + read.required

peer_size = nil
peer_time = Dir.mktmpdir("bench-mirror-apt") do |dir|
  %w[lists/partial cache/archives/partial etc/preferences.d].each { |sub| FileUtils.mkdir_p(File.join(dir, sub)) }
  File.write(File.join(dir, "status"), "")
  sources = REPOSITORIES.map { |repo| "deb [trusted=yes] file://#{repo} bookworm main\n" }.join
  File.write(File.join(dir, "sources.list"), sources)
  Dir.glob("/var/lib/apt/lists/*_{Packages,InRelease,Release}*").each { |file| FileUtils.cp(file, File.join(dir, "lists")) }
  options = ["-o", "Dir::State::status=#{dir}/status", "-o", "Dir::State::Lists=#{dir}/lists",
             "-o", "Dir::Cache=#{dir}/cache", "-o", "Dir::Etc::sourcelist=#{dir}/sources.list",
             "-o", "Dir::Etc::sourceparts=/etc/apt/sources.list.d", "-o", "Dir::Etc::preferencesparts=#{dir}/etc/preferences.d",
             "-o", "APT::Architecture=amd64", "-o", "Debug::NoLocking=1"]
  output, status = Open3.capture2e("apt-get", *options, "update")
  abort "apt-get update: #{output}" unless status.success?
  Timing.median(RUNS) do
    output, status = Open3.capture2e("apt-get", *options, "install", "--simulate", "--no-install-recommends", *names)
    abort "apt-get install --simulate: #{output}" unless status.success?
    peer_size = output.lines.grep(/\AInst /).size
  end
end

component_bytes = Relspec::Apt::HostLists.new.suite_indices("bookworm", "amd64").sum do |_, text|
  text.scan(/^Size: (\d+)$/).sum { |(size)| size.to_i }
end
component_bytes += REPOSITORIES.sum do |repo|
  File.read(File.join(repo, "dists", "bookworm", "main", "binary-amd64", "Packages")).scan(/^Size: (\d+)$/).sum { |(size)| size.to_i }
end
mirror_bytes = closure.binaries.values.sum(&:size)

puts "bench/mirror: demo-child bookworm/amd64, median of #{RUNS}"
puts format("closure: relspec %.2f s (%d packages, every alternative) vs apt-get install --simulate %.2f s " \
            "(%d packages, one alternative each): ratio %.2f", relspec_time, closure.binaries.size, peer_time, peer_size,
            relspec_time / peer_time)
puts format("size: relspec's mirror %.1f MB vs a whole-component mirror %.1f MB: ratio %.4f", mirror_bytes / 1e6,
            component_bytes / 1e6, mirror_bytes.to_f / component_bytes)
